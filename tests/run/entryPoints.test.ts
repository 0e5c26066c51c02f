import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/app/panels/fields';
import { configFromUrl, startConfig, urlWithConfig } from '../../src/app/model/settings';
import { defaultResolution, validateConfig, validateConfigDraft, type ConfigDraft, type ConfigInput } from '../../src/core/config';
import { configSchema } from '../../src/core/config/schema';
import { setPath } from '../../src/core/sweep';
import { configFromAttributes } from '../../src/element/attributes';
import { runSheet } from '../../src/run';
import { useHeadlessContext } from '../gpu/context';

/**
 * One set of defaults (issue 24): a config that leaves fields out gets the schema's defaults
 * through every entry point: the CLI, the library, the element's attributes and the app's links
 * and form. The configs below leave out lloyd and resolution, the fields that used to differ.
 */
const context = useHeadlessContext();
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-entry-'));
const cliBin = join(__dirname, '..', 'cli', 'fromSource.mjs');

const ELLIPSOID: ConfigInput = { surface: { kind: 'ellipsoid', a: 44, b: 27, c: 23 }, cells: 40, seed: 4, sheet: { thickness: 6 } };
const TUBE: ConfigInput = { surface: { kind: 'tube', radius: 20, length: 200 }, cells: 50, seed: 2, sheet: { surfaceRatio: 2 } };

/** An element with these attributes (configFromAttributes reads only getAttribute/hasAttribute). */
function elementWith(attributes: Record<string, string>): Element {
  return {
    getAttribute: (name: string) => attributes[name] ?? null,
    hasAttribute: (name: string) => name in attributes,
  } as unknown as Element;
}

function cliRun(config: ConfigInput, name: string): { config: unknown; headline: { percentScutoids: number; voronoiK: number } } {
  const input = join(dir, `${name}.json`);
  const out = join(dir, `${name}-result.json`);
  writeFileSync(input, JSON.stringify(config));
  const run = spawnSync(process.execPath, [cliBin, 'run', input, '--out', out, '--realizations', '1'], { encoding: 'utf8' });
  expect(run.status, run.stderr).toBe(0);
  return JSON.parse(readFileSync(out, 'utf8'));
}

describe('one set of defaults, whatever the entry point', () => {
  it("the schema is the only place Lloyd iterations and resolution default: 50 and the surface's default", () => {
    const library = validateConfig(ELLIPSOID);
    expect(library.lloyd.maxIterations).toBe(configSchema.properties.lloyd.properties.maxIterations.default);
    expect(library.resolution).toBe(defaultResolution(library));
    expect(validateConfig(TUBE).resolution).toBe(512);
  });

  for (const [name, input, attributes] of [
    ['an ellipsoid', ELLIPSOID, { surface: 'ellipsoid', a: '44', b: '27', c: '23', cells: '40', seed: '4', thickness: '6' }],
    ['a tube', TUBE, { surface: 'tube', radius: '20', length: '200', cells: '50', seed: '2', 'surface-ratio': '2' }],
  ] as const) {
    it(`${name}: the CLI, the library, the element and a link run the same config and give the same headline`, async () => {
      const library = validateConfig(input);
      // The element: attributes over the schema's defaults; the config property likewise.
      expect(configFromAttributes(elementWith(attributes), null)).toEqual(library);
      expect(configFromAttributes(elementWith({}), input)).toEqual(library);
      // The app: a link that leaves the fields out, as it is read and run.
      const fromLink = configFromUrl(`http://localhost/?config=${encodeURIComponent(JSON.stringify(input))}`)!;
      expect(validateConfig(fromLink)).toEqual(library);
      // The CLI and the library give the same result (timings aside).
      const { result } = await runSheet(library, context);
      const cli = cliRun(input, name.replace(/\W/g, ''));
      expect(cli.config).toEqual(library);
      expect(cli.headline).toEqual(JSON.parse(JSON.stringify(result.headline)));
      expect(result.headline!.voronoiK).toBe(51);
    });
  }

  it("an element with no attributes runs the schema's default sheet, as an empty config file does", () => {
    expect(configFromAttributes(elementWith({}), null)).toEqual(validateConfig({}));
  });

  it('the app form: a default resolution follows cells and the surface until the user sets one', () => {
    const set = (draft: ConfigDraft, path: string, value: unknown): ConfigDraft => {
      const spec = FIELDS.find((f) => f.path === path)!;
      if (spec.set) return spec.set(draft, value);
      const next = structuredClone(draft);
      setPath(next, path, value);
      return next;
    };
    let draft = startConfig();
    expect(draft.resolution).toBeNull();
    expect(validateConfig(draft).lloyd.maxIterations).toBe(50);
    draft = set(draft, 'surface.kind', 'ellipsoid');
    const before = validateConfig(draft).resolution;
    expect(before).toBe(defaultResolution(validateConfig(draft)));
    // the order the form is filled in does not matter: more cells, a finer default cube map
    draft = set(draft, 'cells', 800);
    expect(validateConfig(draft).resolution).toBe(defaultResolution({ ...draft, cells: 800 }));
    expect(validateConfig(draft).resolution).toBeGreaterThan(before);
    const typed = validateConfig(validateConfigDraft({ ...draft, cells: 800 }));
    expect(typed).toEqual(validateConfig({ surface: draft.surface, cells: 800, sheet: draft.sheet }));
    // a resolution the user typed stays, whatever the cells
    draft = set(draft, 'resolution', 96);
    draft = set(draft, 'cells', 300);
    expect(validateConfig(draft).resolution).toBe(96);
    // ... but not across planar and closed kinds (texels along a side vs per cube-face edge)
    draft = set(draft, 'surface.kind', 'sphere');
    expect(draft.resolution).toBe(96);
    draft = set(draft, 'surface.kind', 'tube');
    expect(draft.resolution).toBeNull();
    expect(validateConfig(draft).resolution).toBe(512);
  });

  it('a link keeps a default resolution as the default (null), so it reproduces the run', () => {
    const draft = validateConfigDraft(ELLIPSOID);
    const url = urlWithConfig('http://localhost/', draft);
    expect(JSON.parse(new URL(url).searchParams.get('config')!).resolution).toBeNull();
    expect(validateConfig(configFromUrl(url))).toEqual(validateConfig(ELLIPSOID));
  });
});
