/**
 * The exports built from the cells (model/exportFiles.ts, issue 27): a large opened result's
 * files are built in the worker that holds it, from its eager records, its own copies of the
 * label images and the page's result without cell lists (withoutCells); they must be the bytes
 * the page's main thread builds from its lazy records (run/lazyRecords.ts) with the builders
 * themselves (ply.ts, vtk.ts, svg.ts, project.ts, JSON.stringify).
 */
import { describe, expect, it } from 'vitest';
import { withCellRecords } from '../../src/run/cellTables';
import { withLazyCellRecords } from '../../src/run/lazyRecords';
import { runLayeredTube } from '../run/layeredTube';
import { viewStack } from '../../src/view/stack';
import { exportText, heldStack, withoutCells, type ExportRequest } from '../../src/app/model/exportFiles';
import { cellsPly } from '../../src/app/model/ply';
import { cellsVtk } from '../../src/app/model/vtk';
import { unrolledSvg } from '../../src/app/model/svg';
import { projectJson, type ViewState } from '../../src/app/model/project';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

describe('exportFiles', () => {
  it("the worker's files of a held result are the page's, byte for byte, with the page's headline", async () => {
    const output = await runLayeredTube(context);
    // The page: lazy records, and a headline of its own (realizations combined after opening).
    const opened = withLazyCellRecords(withoutCells(output.result), output.tables!);
    const headline = { ...opened.headline!, realizations: 7 };
    const page = viewStack({ result: { ...opened, headline }, labelImages: output.labelImages });
    // The worker: eager records, copies of the label images.
    const held = {
      result: withCellRecords(output.result, output.tables!),
      labelImages: output.labelImages.map((image) => ({ ...image, labels: image.labels.slice() })),
    };
    const worker = heldStack(withoutCells(page.result), held);
    const view: ViewState = { camera: null, visible: [true, false, true], cut: 0.2, highlightScutoids: false, selectedCell: 4 };
    const requests: [ExportRequest, string][] = [
      [{ kind: 'json' }, JSON.stringify(page.result, null, 2)],
      [{ kind: 'ply' }, cellsPly(page)],
      [{ kind: 'vtk' }, cellsVtk(page)],
      [{ kind: 'svg', widthMm: 90 }, unrolledSvg(page, { widthMm: 90 })],
      [
        { kind: 'project', view, sections: { measured: { a: 1 } }, savedAt: '2026-01-02T03:04:05.000Z' },
        projectJson({ result: page.result, labelImages: output.labelImages }, view, { measured: { a: 1 } }, '2026-01-02T03:04:05.000Z'),
      ],
    ];
    for (const [request, expected] of requests) {
      expect(exportText(page, request), request.kind).toBe(expected);
      expect(exportText(worker, request), request.kind).toBe(expected);
    }
    expect(JSON.parse(exportText(worker, { kind: 'json' })).headline.realizations).toBe(7);
    const project = JSON.parse(requests[4][1]);
    expect(project.view).toEqual(view);
    expect(project.sections).toEqual({ measured: { a: 1 } });
    expect(project.result.config).toEqual(JSON.parse(JSON.stringify(output.result.config)));
    expect(() => exportText(worker, { kind: 'project' })).toThrow(/view state/);
  });
});
