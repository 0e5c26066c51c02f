/**
 * The run configuration: its JSON Schema (schema.ts, the single source of truth for every
 * field's type, unit, range, default and description), the TypeScript types computed from it
 * (types.ts, fromSchema.ts), validation with one-line errors (validate.ts), and the grid it
 * implies (feasibility.ts). Beside them, not re-exported here: the schema's fields as plain
 * records for the app's panel, the element's attributes and the generated docs/config.md
 * (schemaFields.ts), and the starting points the app and the element share (presets.ts).
 *
 * Why a schema and not hand-written checks: the same document drives validation, default
 * filling (ajv `useDefaults`), the types and the reference in docs/config.md, so they cannot
 * drift apart. Unions (`surface`, `density`) use ajv's `discriminator` on `kind`, so an error
 * inside a union names the branch the user meant instead of "must match exactly one schema".
 */
export * from './types';
export * from './schema';
export * from './validate';
export * from './feasibility';
export { defaultResolution } from './surfaceLayout';
export * from './methods';
export * from './analysisMethods';
