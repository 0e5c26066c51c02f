/**
 * The measured tissue in the project file (src/app/model/measureProject.ts, projectSections.ts,
 * project.ts): a real simulated sheet and a real measured tissue saved through projectJson, read
 * back through openParsed and the sections; the kept files decode to the same bytes and, measured
 * again, give the saved numbers. Bad sections are refused naming the field.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { validatePlanarConfig } from '../planarConfig';
import { measureTissue, type MeasuredResult } from '../../src/core/measure';
import { fromBase64, toBase64 } from '../../src/app/model/base64';
import { readMeasuredSection, sameMeasurement, type MeasuredSection } from '../../src/app/model/measureProject';
import { openParsed, parseFileJson, projectJson } from '../../src/app/model/project';
import { openSections, registerProjectSection } from '../../src/app/model/projectSections';
import { reassign } from '../../src/app/panels/layerAssign';
import { runSheet, type SheetOutput } from '../../src/run';
import { useHeadlessContext } from '../gpu/context';
import { memoryFile, png16, randomSites, rasterizeVoronoi } from '../measure/images';

const context = useHeadlessContext();
let output: SheetOutput;
let files: { name: string; bytes: Uint8Array }[];
let measured: MeasuredResult;

const measure = (list: { name: string; bytes: Uint8Array }[]) =>
  measureTissue(
    list.map((f) => memoryFile(f.name, f.bytes)),
    { pixelSize: 0.5, periodicX: true, version: 'test' },
  );

beforeAll(async () => {
  const config = validatePlanarConfig({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 64, cells: 12, seed: 1, lloyd: { maxIterations: 1 } });
  output = await runSheet(config, context);
  const sites = randomSites(30, 128, 96, 4);
  const labels = sites.map((_, i) => 2 + 5 * i);
  files = [
    { name: 'basal.png', bytes: png16(rasterizeVoronoi(128, 96, sites, labels, true)) },
    {
      name: 'apical.png',
      bytes: png16(
        rasterizeVoronoi(
          256,
          96,
          sites.map(([x, y]) => [2 * x, y]),
          labels,
          true,
        ),
      ),
    },
  ];
  measured = measure(files);
});

describe('the measured tissue in a project file', () => {
  it('round-trips the files, fields, result and comparison; measured again it gives the saved numbers', async () => {
    const section: MeasuredSection = {
      mode: 'layers',
      files: files.map((f) => ({ name: f.name, type: 'image/png', base64: toBase64(f.bytes) })),
      fields: { 'measure-pixel-size': '0.5', 'measure-periodic': true },
      result: measured,
      comparison: null,
      note: null,
    };
    let opened: unknown = null;
    registerProjectSection('measured', { save: () => section, open: (data) => void (opened = data) });
    const text = projectJson(output, { camera: null, visible: [true, true], cut: 0, highlightScutoids: true, selectedCell: null });
    const file = openParsed(parseFileJson(text, 'p.tissue-sheet.json'), 'p.tissue-sheet.json');
    expect(file.kind).toBe('project');
    await openSections(file.kind === 'project' ? file.sections : undefined, 'p.tissue-sheet.json');
    const back = readMeasuredSection(opened, 'p.tissue-sheet.json');
    expect(back.fields).toEqual(section.fields);
    expect(back.result).toEqual(JSON.parse(JSON.stringify(measured)));
    const bytes = back.files!.map((f, k) => fromBase64(f.base64, `files[${k}]`));
    bytes.forEach((b, k) => expect([...b]).toEqual([...files[k].bytes]));
    const again = measure(back.files!.map((f, k) => ({ name: f.name, bytes: bytes[k] })));
    expect(sameMeasurement(again, back.result)).toBe(true);
    expect(again.cells).toEqual(back.result && (back.result as MeasuredResult).cells);
    // The other order is another tissue: the check tells them apart.
    const swapped = measure(reassign(files, 0, 1));
    expect(sameMeasurement(swapped, back.result)).toBe(false);
  });

  it('encodes any bytes in base64 and back (chunked: large files)', () => {
    const bytes = Uint8Array.from({ length: 200_000 }, (_, k) => (k * 7919) % 256);
    expect([...fromBase64(toBase64(bytes), 'x')]).toEqual([...bytes]);
    expect(toBase64(new Uint8Array([1, 2, 3]))).toBe(Buffer.from([1, 2, 3]).toString('base64'));
  });

  it('refuses a section the page does not know, and malformed measured sections, naming the field', async () => {
    await expect(openSections({ sweeps2: {} }, 'p.json')).rejects.toThrow('p.json: sections.sweeps2: this page does not know');
    await expect(openSections([], 'p.json')).rejects.toThrow('p.json: sections: expected an object');
    const good = { mode: 'volume', files: [{ name: 'a.tif', type: '', base64: 'AAAA' }], fields: {}, result: {}, comparison: null, note: '' };
    expect(() => readMeasuredSection({ ...good, mode: 'other' }, 'p.json')).toThrow('p.json: sections.measured.mode');
    expect(() => readMeasuredSection({ ...good, files: [{ name: 1 }] }, 'p.json')).toThrow('sections.measured.files[0]');
    expect(() => readMeasuredSection({ ...good, fields: { a: {} } }, 'p.json')).toThrow('sections.measured.fields.a');
    expect(() => readMeasuredSection({ ...good, result: null }, 'p.json')).toThrow('sections.measured.result');
    expect(() => fromBase64('***', 'files[0]')).toThrow('files[0]: not base64');
    expect(readMeasuredSection(good, 'p.json').mode).toBe('volume');
  });

  it('reassigns a layer by swapping with the file that had it', () => {
    expect(reassign(['a', 'b', 'c'], 0, 2)).toEqual(['c', 'b', 'a']);
    expect(reassign(['a', 'b', 'c'], 1, 1)).toEqual(['a', 'b', 'c']);
  });
});
