"""The published tube grid with NumPy/SciPy, for comparison with bench/exactSweep.ts.

Same table: Voronoi 1-10 x s = 1 ... 10 (12 ratios) x 20 realizations, lab protocol.
Lloyd: exact Voronoi cells (scipy.spatial.Voronoi on the sites tripled around the tube, cells
clipped to the tube's ends), centroids in closed form. Layers 1 : 0.25 : 10, neighbours and
validity the way the lab's delaunayEuler3DPredefinedSeeds.m does it (Delaunay of the tripled
sites; triangles whose circumcentre lies beyond an end mark their cells invalid; neighbours from
the triangles with circumcentres inside the middle copy). Run: python3 bench/exactSweep.py
"""
import sys
import time
import resource
import numpy as np
from scipy.spatial import Delaunay, Voronoi

W, H, CELLS, SPACING = 512.0, 4096.0, 200, 5.0
RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10]
LAYERS = [1 + 0.25 * k for k in range(37)]
REALIZATIONS = int(sys.argv[sys.argv.index('--realizations') + 1]) if '--realizations' in sys.argv else 20


def place(rng):
    pts = np.empty((CELLS, 2))
    n = 0
    while n < CELLS:
        p = rng.random(2) * (W, H)
        if n:
            d = pts[:n] - p
            d[:, 0] -= W * np.round(d[:, 0] / W)
            if np.min(np.einsum('ij,ij->i', d, d)) < SPACING ** 2:
                continue
        pts[n] = p
        n += 1
    return pts


def clip(poly, value, sign):
    out = []
    for k in range(len(poly)):
        a, b = poly[k], poly[(k + 1) % len(poly)]
        da, db = sign * (a[1] - value), sign * (b[1] - value)
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            t = da / (da - db)
            out.append(a + (b - a) * t)
    return out


def lloyd_step(sites):
    tripled = np.vstack([sites, sites + (W, 0), sites - (W, 0)])
    vor = Voronoi(tripled)
    out = sites.copy()
    far = 1e5
    for i in range(CELLS):
        region = vor.regions[vor.point_region[i]]
        if -1 in region or not region:
            # Unbounded (a site next to an end): bound it with the mirror images across both ends.
            mirrored = np.vstack([tripled, tripled * (1, -1), tripled * (1, -1) + (0, 2 * H)])
            vor2 = Voronoi(mirrored)
            region = vor2.regions[vor2.point_region[i]]
            poly = [vor2.vertices[v] for v in region]
        else:
            poly = [vor.vertices[v] for v in region]
        poly = clip(clip(poly, 0.0, 1), H, -1)
        p = np.array(poly)
        x, y = p[:, 0], p[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cross = x * yn - xn * y
        a = cross.sum() / 2
        out[i] = ((x + xn) * cross).sum() / (6 * a), ((y + yn) * cross).sum() / (6 * a)
    out[:, 0] %= W
    return out


def layer(sites, s):
    w = W * s
    pts = sites * (s, 1)
    tripled = np.vstack([pts, pts + (w, 0), pts + (2 * w, 0)])
    tri = Delaunay(tripled)
    simplices = tri.simplices
    a, b, c = tripled[simplices[:, 0]], tripled[simplices[:, 1]], tripled[simplices[:, 2]]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    a2, b2, c2 = (a ** 2).sum(1), (b ** 2).sum(1), (c ** 2).sum(1)
    ux = (a2 * (b[:, 1] - c[:, 1]) + b2 * (c[:, 1] - a[:, 1]) + c2 * (a[:, 1] - b[:, 1])) / d
    uy = (a2 * (c[:, 0] - b[:, 0]) + b2 * (a[:, 0] - c[:, 0]) + c2 * (b[:, 0] - a[:, 0])) / d
    middle = (ux > w) & (ux <= 2 * w)
    inside = (uy > 0) & (uy <= H)
    invalid = np.unique(simplices[middle & ~inside] % CELLS)
    keep = simplices[middle & inside] % CELLS
    edges = np.vstack([keep[:, [0, 1]], keep[:, [1, 2]], keep[:, [2, 0]]])
    edges = np.vstack([edges, edges[:, ::-1]])
    edges = edges[edges[:, 0] != edges[:, 1]]
    neigh = [set() for _ in range(CELLS)]
    for i, j in np.unique(edges, axis=0):
        neigh[i].add(j)
    return neigh, invalid


def table(sites):
    layers = [layer(sites, s) for s in LAYERS]
    invalid = set()
    for _, bad in layers:
        invalid.update(bad.tolist())
    valid = [i for i in range(CELLS) if i not in invalid]
    targets = {int(round((s - 1) / 0.25)): t for t, s in enumerate(RATIOS)}
    scut = np.zeros(len(RATIOS))
    n3d = np.zeros(len(RATIOS))
    for i in valid:
        union, won, lost = set(layers[0][0][i]), set(), set()
        for k in range(len(LAYERS)):
            if k:
                prev, cur = layers[k - 1][0][i], layers[k][0][i]
                lost |= prev - cur
                won |= cur - prev
                union |= cur
            if k in targets:
                scut[targets[k]] += 1 if won or lost else 0
                n3d[targets[k]] += len(union)
    return 100 * scut / len(valid), n3d / len(valid)


start = time.perf_counter()
percent = np.zeros((10, len(RATIOS)))
lloyd_s = 0.0
for r in range(REALIZATIONS):
    sites = place(np.random.default_rng(r + 1))
    for k in range(10):
        if k:
            t = time.perf_counter()
            sites = lloyd_step(sites)
            lloyd_s += time.perf_counter() - t
        pct, _ = table(sites)
        percent[k] += pct / REALIZATIONS
total = time.perf_counter() - start
runs = REALIZATIONS * 10 * len(RATIOS)
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(f"NumPy/SciPy, lab protocol: {runs} runs in {total:.2f} s = {runs / total:.0f} runs/s (Lloyd {lloyd_s:.2f} s), peak RSS {peak:.0f} MiB")
print('  k   ' + ''.join(f'{s:>6}' for s in RATIOS))
for k in range(10):
    print(f'  {k + 1:>2}  ' + ''.join(f'{v:6.1f}' for v in percent[k]))
