"""The published tube grid with NumPy/SciPy: the fair baseline of `tissue-sheet sweep` (issue 27).

Same grid and protocol as examples/published-tube-sweep-lab.json and bench/exactSweep.ts:
Voronoi 1-10 x s = 1 ... 10 (12 ratios) x 20 realizations, lab protocol, exact adjacency, on the
512 x 4096 tube (periodic around, open ends), 200 sites at least 5 apart.

Fair means: one scipy.spatial.Delaunay per tessellation and no Python loop over cells.

- Lloyd (exact, uniform density): one Delaunay of the sites copied 3 x around the tube and
  mirrored across both ends (9 copies: a cell of the mirrored set is exactly the cell clipped to
  the tube), circumcentres = Voronoi vertices, each cell's area and centroid summed over the fan
  of triangles (site, circumcentre, next circumcentre around the site) with np.bincount.
  Voronoi k = the sites after k - 1 iterations; one Lloyd run per realization serves k = 1..10.
- Layers s = 1 : 0.25 : 10 (37): one Delaunay each of the sites scaled by s around the tube and
  tripled; a Voronoi vertex (circumcentre) of the middle copy beyond an end marks its three
  cells as touching that end (= their clipped cells reach it), the others give the neighbour
  pairs; neighbour sets are 200 x 200 boolean matrices. The layers serve every ratio of a
  realization and Voronoi k, as the TypeScript sweep's do.
- Lab protocol: a cell touching an end on any layer 1..10 is excluded from every statistic;
  per ratio s (the stack 1, 1.25, ..., s): % scutoids (won or lost a neighbour between layers),
  transitions |U lost| + |U won| accumulated layer to layer, 3D neighbours |U N_k|, and the
  basal and apical polygon distributions, as matrix operations over all cells at once.

  python3 bench/exactSweep.py [--realizations 20] [--json out.json]
"""
import json
import resource
import sys
import time

import numpy as np
from scipy.spatial import Delaunay

W, H, CELLS, SPACING = 512.0, 4096.0, 200, 5.0
RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10]
STEP = 0.25
LAYERS = [1 + STEP * k for k in range(37)]
TARGET = [int(round((s - 1) / STEP)) for s in RATIOS]
VORONOI = 10
SIDES = np.arange(3, 11)


def option(name, fallback):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else fallback


REALIZATIONS = int(option('--realizations', 20))


def place(rng):
    """CELLS random sites, pairwise (periodic) distance >= SPACING: redraw offenders, vectorized."""
    pts = rng.random((CELLS, 2)) * (W, H)
    while True:
        d = pts[:, None, :] - pts[None, :, :]
        d[..., 0] -= W * np.round(d[..., 0] / W)
        close = np.einsum('ijk,ijk->ij', d, d) < SPACING ** 2
        np.fill_diagonal(close, False)
        bad = np.triu(close).any(axis=0)
        if not bad.any():
            return pts
        pts[bad] = rng.random((int(bad.sum()), 2)) * (W, H)


def circumcentres(p, simplices):
    a, b, c = p[simplices[:, 0]], p[simplices[:, 1]], p[simplices[:, 2]]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    a2, b2, c2 = (a ** 2).sum(1), (b ** 2).sum(1), (c ** 2).sum(1)
    ux = (a2 * (b[:, 1] - c[:, 1]) + b2 * (c[:, 1] - a[:, 1]) + c2 * (a[:, 1] - b[:, 1])) / d
    uy = (a2 * (c[:, 0] - b[:, 0]) + b2 * (a[:, 0] - c[:, 0]) + c2 * (b[:, 0] - a[:, 0])) / d
    return np.stack([ux, uy], axis=1), d


def lloyd_step(sites):
    """One exact Lloyd iteration on the tube (uniform density), one Delaunay."""
    copies = [sites + (dx, 0) for dx in (0, W, -W)]
    around = np.vstack(copies)
    pts = np.vstack([around, around * (1, -1), around * (1, -1) + (0, 2 * H)])  # originals first
    tri = Delaunay(pts)
    simp, nb = tri.simplices, tri.neighbors
    cc, d = circumcentres(pts, simp)
    # Make every triangle counter-clockwise (d > 0); its neighbours follow its vertices.
    cw = d < 0
    simp = simp.copy()
    nb = nb.copy()
    simp[cw] = simp[cw][:, [0, 2, 1]]
    nb[cw] = nb[cw][:, [0, 2, 1]]
    # Around vertex v of a ccw triangle t, the next triangle counter-clockwise is across the edge
    # (v, v+2), i.e. opposite vertex v+1.
    site, nxt, cur = [], [], []
    for v in range(3):
        own = simp[:, v] < CELLS
        site.append(simp[own, v])
        cur.append(np.flatnonzero(own))
        nxt.append(nb[own, (v + 1) % 3])
    site, cur, nxt = np.concatenate(site), np.concatenate(cur), np.concatenate(nxt)
    p = pts[site]
    a = cc[cur] - p
    b = cc[nxt] - p
    cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    area = np.bincount(site, cross, CELLS) / 2
    cx = np.bincount(site, cross * (a[:, 0] + b[:, 0]), CELLS) / 6
    cy = np.bincount(site, cross * (a[:, 1] + b[:, 1]), CELLS) / 6
    out = sites + np.stack([cx / area, cy / area], axis=1)
    out[:, 0] %= W
    out[:, 1] = np.clip(out[:, 1], 0, H)
    return out


def layer(sites, s):
    """Neighbour matrix and end contacts on the surface at ratio s, one Delaunay."""
    w = W * s
    pts = sites * (s, 1)
    tripled = np.vstack([pts, pts + (w, 0), pts + (2 * w, 0)])
    simp = Delaunay(tripled).simplices
    cc, _ = circumcentres(tripled, simp)
    middle = (cc[:, 0] > w) & (cc[:, 0] <= 2 * w)
    inside = (cc[:, 1] > 0) & (cc[:, 1] < H)
    ends = np.zeros(CELLS, bool)
    ends[simp[middle & ~inside] % CELLS] = True
    keep = simp[middle & inside] % CELLS
    adj = np.zeros((CELLS, CELLS), bool)
    for u, v in ((0, 1), (1, 2), (2, 0)):
        adj[keep[:, u], keep[:, v]] = True
        adj[keep[:, v], keep[:, u]] = True
    np.fill_diagonal(adj, False)
    return adj, ends


def polygons(adj, valid):
    n = adj[valid].sum(1)
    counts = np.array([(n == k).sum() for k in SIDES[:-1]] + [(n >= 10).sum()])
    return counts / max(1, valid.sum()), n.mean() if valid.any() else np.nan


def table(sites):
    """Every ratio of one realization and Voronoi k, in one pass over the 37 layers."""
    layers = [layer(sites, s) for s in LAYERS]
    invalid = np.zeros(CELLS, bool)
    for _, ends in layers:
        invalid |= ends
    valid = ~invalid
    n = valid.sum()
    basal = polygons(layers[0][0], valid)
    union = layers[0][0].copy()
    won = np.zeros_like(union)
    lost = np.zeros_like(union)
    rows = []
    targets = {k: t for t, k in enumerate(TARGET)}
    for k, (adj, _) in enumerate(layers):
        if k:
            prev = layers[k - 1][0]
            lost |= prev & ~adj
            won |= adj & ~prev
            union |= adj
        if k in targets:
            changes = (won[valid].sum(1) + lost[valid].sum(1))
            apical = polygons(adj, valid)
            rows.append({
                'ratio': RATIOS[targets[k]],
                'validCells': int(n),
                'percentScutoids': 100 * float((changes > 0).mean()),
                'meanTransitions': float(changes.mean()),
                'meanNeighbours3D': float(union[valid].sum(1).mean()),
                'basal': {'meanSides': float(basal[1]), 'polygons': basal[0].tolist()},
                'apical': {'meanSides': float(apical[1]), 'polygons': apical[0].tolist()},
            })
    return rows


def main():
    start = time.perf_counter()
    results = []  # [realization][k][ratio]
    lloyd_s = 0.0
    delaunays = 0
    for r in range(REALIZATIONS):
        sites = place(np.random.default_rng(r + 1))
        per_k = []
        for k in range(VORONOI):
            if k:
                t = time.perf_counter()
                sites = lloyd_step(sites)
                lloyd_s += time.perf_counter() - t
                delaunays += 1
            per_k.append(table(sites))
            delaunays += len(LAYERS)
        results.append(per_k)
    total = time.perf_counter() - start
    runs = REALIZATIONS * VORONOI * len(RATIOS)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f'NumPy/SciPy, lab protocol: {runs} runs in {total:.2f} s = {runs / total:.0f} runs/s '
          f'(Lloyd {lloyd_s:.2f} s, {delaunays} Delaunay triangulations), peak RSS {peak:.0f} MiB')
    print('% scutoids (mean over realizations), rows Voronoi k, columns s:')
    print('  k   ' + ''.join(f'{s:>6}' for s in RATIOS))
    for k in range(VORONOI):
        cells = [np.mean([results[r][k][t]['percentScutoids'] for r in range(REALIZATIONS)]) for t in range(len(RATIOS))]
        print(f'  {k + 1:>2}  ' + ''.join(f'{v:6.1f}' for v in cells))
    if '--json' in sys.argv:
        with open(option('--json', ''), 'w') as f:
            json.dump({'seconds': total, 'runs': runs, 'realizations': REALIZATIONS, 'table': results}, f)


if __name__ == '__main__':
    main()
