/** Reference curves (docs/reference-curves.md): the format, its CSV form, matching to a sweep. */
export * from './format';
export * from './referenceCsv';
export * from './match';
export * from './interval';
import { parseReferenceJson, ReferenceError, type ReferenceDocument } from './format';
import { parseReferenceCsv } from './referenceCsv';

/** Reads a reference file, JSON or CSV (by its name, else by its first character); errors start with the name. */
export function readReferenceFile(name: string, text: string): ReferenceDocument {
  const json = /\.json$/i.test(name) || (!/\.csv$/i.test(name) && /^\s*[[{]/.test(text));
  try {
    return json ? parseReferenceJson(text) : parseReferenceCsv(text);
  } catch (error) {
    if (error instanceof ReferenceError) throw new ReferenceError(`${name}: ${error.message}`);
    throw error;
  }
}
