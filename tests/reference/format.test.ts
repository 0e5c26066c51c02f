import { describe, expect, it } from 'vitest';
import {
  configDifferences,
  overlayFor,
  parseReferenceCsv,
  parseReferenceJson,
  readReferenceFile,
  REFERENCE_LIMITS,
  ReferenceError,
  type ReferenceCurve,
} from '../../src/core/reference';

const SOURCE = 'digitised from a figure, for the test';
const point = (x: number, percent: number, extra: Record<string, unknown> = {}) => ({ x, percent, source: SOURCE, ...extra });
const curve = (extra: Record<string, unknown> = {}) => ({
  id: 'c1',
  label: 'A curve',
  kind: 'data',
  quantity: 'surfaceRatio',
  points: [point(1, 0), point(2, 50, { sd: 3, n: 5 })],
  ...extra,
});
const docOf = (extra: Record<string, unknown> = {}) => ({ format: 'tissue-sheet-reference-curves', version: 1, curves: [curve()], ...extra });
const json = (value: unknown) => JSON.stringify(value);

/** The error a bad input gives: one line, a ReferenceError. */
function errorOf(run: () => unknown): string {
  try {
    run();
  } catch (error) {
    expect(error).toBeInstanceOf(ReferenceError);
    const message = (error as Error).message;
    expect(message.split('\n')).toHaveLength(1);
    return message;
  }
  throw new Error('expected an error');
}

const CSV_HEADER = 'curve,label,kind,quantity,source,x,percent,sd,n';

describe('reference curves, JSON', () => {
  it('reads a good document: points sorted by x, sd and n optional, fixed kept', () => {
    const doc = parseReferenceJson(
      json(
        docOf({
          title: 'T',
          provenance: { by: 'hand', list: [1, { a: 2 }] },
          curves: [curve({ fixed: { voronoiK: 3 }, points: [point(3, 90), point(1, 0, { sd: null })] })],
        }),
      ),
    );
    expect(doc.title).toBe('T');
    const [c] = doc.curves;
    expect(c.points.map((p) => p.x)).toEqual([1, 3]);
    expect(c.points[0]).toEqual({ x: 1, percent: 0, sd: null, n: null, source: SOURCE });
    expect(c.fixed).toEqual({ voronoiK: 3 });
  });

  it.each<[string, unknown, RegExp]>([
    ['not JSON', '{', /^file: not JSON/],
    ['not an object', [], /^document: must be a JSON object/],
    ['wrong format', docOf({ format: 'other' }), /^format: must be "tissue-sheet-reference-curves"/],
    ['wrong version', docOf({ version: 2 }), /^version: must be 1/],
    ['unknown field', docOf({ extra: 1 }), /^document: unknown field "extra"/],
    ['no curves', docOf({ curves: [] }), /^curves: the file holds no curve/],
    ['curves not an array', docOf({ curves: {} }), /^curves: must be an array/],
    ['missing source', docOf({ curves: [curve({ points: [{ x: 1, percent: 2 }] })] }), /^curves\[0\]\.points\[0\]: missing field "source"/],
    ['empty source', docOf({ curves: [curve({ points: [point(1, 2, { source: '  ' })] })] }), /^curves\[0\]\.points\[0\]\.source: every point needs a source/],
    ['percent above 100', docOf({ curves: [curve({ points: [point(1, 120)] })] }), /^curves\[0\]\.points\[0\]\.percent: 120 is outside 0\.\.100/],
    ['percent below 0', docOf({ curves: [curve({ points: [point(1, -1)] })] }), /percent: -1 is outside 0\.\.100/],
    ['percent as text', docOf({ curves: [curve({ points: [point(1, '5' as unknown as number)] })] }), /percent: must be a finite number, got "5"/],
    ['x null (NaN in JSON)', docOf({ curves: [curve({ points: [point(Number.NaN, 5)] })] }), /points\[0\]\.x: must be a finite number, got null/],
    ['negative sd', docOf({ curves: [curve({ points: [point(1, 5, { sd: -1 })] })] }), /sd: -1 is negative/],
    ['fractional n', docOf({ curves: [curve({ points: [point(1, 5, { n: 2.5 })] })] }), /n: 2\.5 is not a whole number/],
    ['unknown point field', docOf({ curves: [curve({ points: [point(1, 5, { y: 1 })] })] }), /points\[0\]: unknown field "y"/],
    ['bad kind', docOf({ curves: [curve({ kind: 'fit' })] }), /^curves\[0\]\.kind: must be "model" or "data"/],
    ['bad quantity', docOf({ curves: [curve({ quantity: 'surface ratio' })] }), /^curves\[0\]\.quantity: "surface ratio" is not a quantity name/],
    ['prototype quantity', docOf({ curves: [curve({ quantity: 'sheet.constructor' })] }), /quantity: "constructor" is not allowed/],
    ['empty label', docOf({ curves: [curve({ label: '' })] }), /^curves\[0\]\.label: must not be empty/],
    ['repeated x', docOf({ curves: [curve({ points: [point(1, 0), point(1, 5)] })] }), /^curves\[0\]\.points: x = 1 appears twice/],
    ['no points', docOf({ curves: [curve({ points: [] })] }), /^curves\[0\]\.points: the curve has no point/],
    ['repeated id', docOf({ curves: [curve(), curve()] }), /^curve "c1": the id is used by two curves/],
    ['bad fixed', docOf({ curves: [curve({ fixed: { voronoiK: 'four' } })] }), /fixed\.voronoiK: must be a finite number/],
  ])('refuses %s with a message naming the field', (_name, input, pattern) => {
    expect(errorOf(() => parseReferenceJson(typeof input === 'string' ? input : json(input)))).toMatch(pattern);
  });

  it('refuses __proto__, constructor and prototype keys anywhere, and never touches a prototype', () => {
    for (const key of ['__proto__', 'constructor', 'prototype']) {
      expect(errorOf(() => parseReferenceJson(`{"format":"tissue-sheet-reference-curves","version":1,"${key}":{"x":1},"curves":[]}`))).toMatch(
        new RegExp(`^document: the key "${key}" is not allowed`),
      );
      expect(errorOf(() => parseReferenceJson(json(docOf()).replace('"id":"c1"', `"${key}":{"polluted":1},"id":"c1"`)))).toMatch(/^curves\[0\]: the key/);
      expect(errorOf(() => parseReferenceJson(json(docOf({ provenance: { a: [{ b: 1 }] } })).replace('"b":1', `"${key}":1`)))).toMatch(
        /^provenance\.a\[0\]: the key/,
      );
      expect(errorOf(() => parseReferenceJson(json(docOf({ curves: [curve({ fixed: {} })] })).replace('"fixed":{}', `"fixed":{"${key}":1}`)))).toMatch(/fixed/);
    }
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });

  it('bounds the work before reading points: file size, curves, points, nesting', () => {
    expect(errorOf(() => parseReferenceJson(' '.repeat(REFERENCE_LIMITS.maxChars + 1)))).toMatch(/^file: larger than/);
    const many = Array.from({ length: REFERENCE_LIMITS.maxCurves + 1 }, (_, k) => curve({ id: `c${k}` }));
    expect(errorOf(() => parseReferenceJson(json(docOf({ curves: many }))))).toMatch(/^curves: 65 curves, more than 64/);
    const points = Array.from({ length: REFERENCE_LIMITS.maxPoints + 1 }, (_, k) => ({ x: k, percent: 1, source: 's' }));
    expect(errorOf(() => parseReferenceJson(json(docOf({ curves: [curve({ points })] }))))).toMatch(/^curves: more than 10000 points/);
    let deep: unknown = 1;
    for (let k = 0; k < 40; k++) deep = { a: deep };
    expect(errorOf(() => parseReferenceJson(json(docOf({ provenance: deep }))))).toMatch(/^provenance(\.a)+: nested deeper than 16 levels/);
  });
});

describe('reference curves, CSV', () => {
  it('reads a good file: columns in any order, quoted cells, empty sd and n, no final newline, curves grouped by id', () => {
    const text = [
      'quantity,curve,label,kind,source,x,percent,sd,n',
      'surfaceRatio,p,"Paper, Fig. 2",data,"Smith et al. 2020, Fig. 2b ""model"" panel",2,40.5,,',
      'surfaceRatio,p,"Paper, Fig. 2",data,"Smith et al. 2020, Fig. 2b ""model"" panel",1,0,1.5,20',
      'voronoiK,q,Q,model,computed,1,10,,',
    ].join('\r\n');
    const doc = parseReferenceCsv(text);
    expect(doc.curves.map((c) => c.id)).toEqual(['p', 'q']);
    const [p] = doc.curves;
    expect(p.label).toBe('Paper, Fig. 2');
    expect(p.points).toEqual([
      { x: 1, percent: 0, sd: 1.5, n: 20, source: 'Smith et al. 2020, Fig. 2b "model" panel' },
      { x: 2, percent: 40.5, sd: null, n: null, source: 'Smith et al. 2020, Fig. 2b "model" panel' },
    ]);
    // sd and n may be left out of the header.
    expect(parseReferenceCsv('curve,label,kind,quantity,source,x,percent\na,A,data,voronoiK,s,1,2\n').curves[0].points[0].sd).toBeNull();
  });

  it.each<[string, string, RegExp]>([
    ['an empty file', '', /^file: empty/],
    ['an unknown column', 'curve,label,kind,quantity,source,x,percent,weight\n', /^line 1: unknown column "weight"/],
    ['a missing column', 'curve,label,kind,source,x,percent\n', /^line 1: missing column "quantity"/],
    ['a repeated column', 'curve,label,kind,quantity,source,x,percent,x\n', /^line 1: column "x" appears twice/],
    ['no rows', `${CSV_HEADER}\n`, /^file: no row after the header/],
    ['a short row', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,2\n`, /^line 2: 7 cells, the header has 9/],
    ['NaN', `${CSV_HEADER}\na,A,data,surfaceRatio,s,NaN,2,,\n`, /^line 2, column x: "NaN" is not a number/],
    ['Infinity', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,Infinity,,\n`, /^line 2, column percent: "Infinity" is not a number/],
    ['a percent above 100', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,100.5,,\n`, /^line 2, column percent: 100.5 is outside 0\.\.100/],
    ['an empty percent', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,,,\n`, /^line 2, column percent: empty/],
    ['a missing source', `${CSV_HEADER}\na,A,data,surfaceRatio,,1,5,,\n`, /^line 2, column source: every point needs a source/],
    ['a bad kind', `${CSV_HEADER}\na,A,fit,surfaceRatio,s,1,5,,\n`, /^line 2, column kind: must be "model" or "data"/],
    ['a bad n', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,5,,0\n`, /^line 2, column n: 0 is not a whole number/],
    [
      'a label that changes within a curve',
      `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,5,,\na,B,data,surfaceRatio,s,2,6,,\n`,
      /^line 3, column label: curve "a" has label "A" on line 2/,
    ],
    ['a repeated x', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,5,,\na,A,data,surfaceRatio,s,1,6,,\n`, /^curve "a": x = 1 appears twice/],
    ['an unclosed quote', `${CSV_HEADER}\na,A,data,surfaceRatio,"s,1,5,,\n`, /a quoted cell is not closed/],
    ['a prototype quantity', `${CSV_HEADER}\na,A,data,constructor,s,1,5,,\n`, /^line 2, column quantity: "constructor" is not allowed/],
  ])('refuses %s with a message naming the line and column', (_name, text, pattern) => {
    expect(errorOf(() => parseReferenceCsv(text))).toMatch(pattern);
  });

  it('bounds rows and curves before reading them', () => {
    const row = 'a,A,data,surfaceRatio,s,1,5,,\n';
    expect(errorOf(() => parseReferenceCsv(CSV_HEADER + '\n' + row.repeat(REFERENCE_LIMITS.maxPoints + 1)))).toMatch(/^file: more than 10000 rows/);
    const curves = Array.from({ length: 65 }, (_, k) => `c${k},C,data,surfaceRatio,s,1,5,,`).join('\n');
    expect(errorOf(() => parseReferenceCsv(`${CSV_HEADER}\n${curves}\n`))).toMatch(/^line 66: more than 64 curves/);
  });

  it('readReferenceFile picks JSON or CSV by name or content and names the file in errors', () => {
    expect(readReferenceFile('a.json', json(docOf())).curves).toHaveLength(1);
    expect(readReferenceFile('digitised', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,5,,\n`).curves).toHaveLength(1);
    expect(errorOf(() => readReferenceFile('fig2.csv', `${CSV_HEADER}\na,A,data,surfaceRatio,s,1,500,,\n`))).toMatch(
      /^fig2\.csv: line 2, column percent: 500 is outside/,
    );
  });
});

describe('matching curves to a sweep', () => {
  const c = (id: string, quantity: string, fixed: Record<string, number> = {}): ReferenceCurve => ({
    id,
    label: id,
    kind: 'model',
    quantity,
    fixed,
    points: [{ x: 1, percent: 0, sd: null, n: null, source: 's' }],
  });
  const curves = [
    c('k1', 'surfaceRatio', { voronoiK: 1 }),
    c('k4', 'surfaceRatio', { voronoiK: 4 }),
    c('s2', 'voronoiK', { surfaceRatio: 2 }),
    c('free', 'surfaceRatio'),
  ];

  it('draws only curves whose x is the swept field, says why the others are not drawn', () => {
    const overlay = overlayFor(curves, 'sheet.thickness', {});
    expect(overlay.drawn).toEqual([]);
    expect(overlay.skipped[0].reason).toBe('x is surfaceRatio, the sweep varies sheet.thickness');
    const byK = overlayFor(curves, 'lloyd.maxIterations', { sheet: { surfaceRatio: 2 } });
    expect(byK.drawn.map((x) => x.id)).toEqual(['s2']);
  });

  it("keeps the curves at the sweep's own fixed values when some match, all of them otherwise", () => {
    const at4 = overlayFor(curves, 'sheet.surfaceRatio', { lloyd: { maxIterations: 3 } });
    expect(at4.drawn.map((x) => x.id)).toEqual(['k4']);
    expect(at4.skipped.find((s) => s.curve.id === 'k1')!.reason).toBe("held at another voronoiK than the sweep's voronoiK = 4");
    expect(overlayFor(curves, 'sheet.surfaceRatio', { lloyd: { maxIterations: 49 } }).drawn.map((x) => x.id)).toEqual(['k1', 'k4', 'free']);
  });

  it("lists where a sweep's configuration differs from the one a set records", () => {
    const doc = {
      ...parseReferenceJson(json(docOf())),
      provenance: { spec: { base: { cells: 200, sheet: { protocol: 'lab' }, surface: { kind: 'tube', radius: 81.48733086305042 } } } },
    };
    expect(configDifferences(doc, { cells: 200, sheet: { protocol: 'lab' }, surface: { kind: 'tube', radius: 81.487330863 } })).toEqual([]);
    expect(configDifferences(doc, { cells: 60, sheet: { protocol: 'default' }, surface: { kind: 'tube', radius: 40 } }).map((d) => d.field)).toEqual([
      'surface.radius',
      'cells',
      'sheet.protocol',
    ]);
  });
});
