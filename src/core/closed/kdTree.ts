/**
 * Static 3D k-d tree over points (sites, triangle centroids) with k-nearest-neighbour queries
 * into caller-owned typed arrays, so the restricted Voronoi loops never allocate.
 *
 * Build: the point ids are permuted in place so that every node owns a contiguous range
 * [lo, hi) of `order`; a node splits its range at the median of its widest bounding-box axis
 * (quickselect), down to leaves of at most LEAF points. Queries walk the tree with an explicit
 * stack, nearer child first, and skip a subtree when the squared distance to its splitting
 * plane is not below the current k-th best.
 */

const LEAF = 8;

export class KdTree3 {
  readonly count: number;
  private readonly xyz: Float64Array;
  /** Point ids, permuted so that every node's points are order[lo .. hi). */
  private readonly order: Int32Array;
  private readonly lo: Int32Array;
  private readonly hi: Int32Array;
  private readonly axis: Int8Array; // -1 for a leaf
  private readonly split: Float64Array;
  private readonly left: Int32Array;
  private readonly right: Int32Array;
  private nodes = 0;
  private readonly stack: Int32Array;
  private readonly stackD: Float64Array;

  /** `points`: x, y, z per point (at least 3 count values). */
  constructor(points: ArrayLike<number>, count: number) {
    this.count = count;
    this.xyz = new Float64Array(3 * count);
    for (let k = 0; k < 3 * count; k++) this.xyz[k] = points[k];
    this.order = new Int32Array(count);
    for (let i = 0; i < count; i++) this.order[i] = i;
    const maxNodes = Math.max(1, 2 * Math.ceil(count / (LEAF / 2)) + 1);
    this.lo = new Int32Array(maxNodes);
    this.hi = new Int32Array(maxNodes);
    this.axis = new Int8Array(maxNodes);
    this.split = new Float64Array(maxNodes);
    this.left = new Int32Array(maxNodes);
    this.right = new Int32Array(maxNodes);
    this.stack = new Int32Array(256);
    this.stackD = new Float64Array(256);
    if (count > 0) this.build(0, count);
  }

  private build(lo: number, hi: number): number {
    const node = this.nodes++;
    this.lo[node] = lo;
    this.hi[node] = hi;
    if (hi - lo <= LEAF) {
      this.axis[node] = -1;
      return node;
    }
    const p = this.xyz,
      o = this.order;
    let minX = Infinity,
      minY = Infinity,
      minZ = Infinity,
      maxX = -Infinity,
      maxY = -Infinity,
      maxZ = -Infinity;
    for (let k = lo; k < hi; k++) {
      const b = 3 * o[k];
      if (p[b] < minX) minX = p[b];
      if (p[b] > maxX) maxX = p[b];
      if (p[b + 1] < minY) minY = p[b + 1];
      if (p[b + 1] > maxY) maxY = p[b + 1];
      if (p[b + 2] < minZ) minZ = p[b + 2];
      if (p[b + 2] > maxZ) maxZ = p[b + 2];
    }
    const ex = maxX - minX,
      ey = maxY - minY,
      ez = maxZ - minZ;
    const ax = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
    const mid = (lo + hi) >> 1;
    this.select(lo, hi - 1, mid, ax);
    this.axis[node] = ax;
    this.split[node] = p[3 * o[mid] + ax];
    this.left[node] = this.build(lo, mid);
    this.right[node] = this.build(mid, hi);
    return node;
  }

  /** Quickselect: order[k] gets the point with the k-th smallest coordinate `ax` in [l, r]. */
  private select(l: number, r: number, k: number, ax: number): void {
    const p = this.xyz,
      o = this.order;
    while (r > l) {
      const pivot = p[3 * o[(l + r) >> 1] + ax];
      let i = l,
        j = r;
      while (i <= j) {
        while (p[3 * o[i] + ax] < pivot) i++;
        while (p[3 * o[j] + ax] > pivot) j--;
        if (i <= j) {
          const t = o[i];
          o[i] = o[j];
          o[j] = t;
          i++;
          j--;
        }
      }
      if (k <= j) r = j;
      else if (k >= i) l = i;
      else return;
    }
  }

  /**
   * The k nearest points to (x, y, z), closest first (ties by id), into outIds / outD2
   * (squared distances). Returns how many were found (min(k, count)). `skip` (optional) is
   * a point id left out (the query site itself).
   */
  knn(x: number, y: number, z: number, k: number, outIds: Int32Array, outD2: Float64Array, skip = -1): number {
    if (this.count === 0 || k <= 0) return 0;
    const p = this.xyz,
      o = this.order;
    let found = 0;
    let worst = Infinity; // k-th best squared distance once found === k
    let top = 0;
    this.stack[top] = 0;
    this.stackD[top++] = 0;
    while (top > 0) {
      top--;
      const node = this.stack[top];
      if (found === k && this.stackD[top] >= worst) continue;
      const ax = this.axis[node];
      if (ax < 0) {
        for (let q = this.lo[node]; q < this.hi[node]; q++) {
          const id = o[q];
          if (id === skip) continue;
          const dx = p[3 * id] - x,
            dy = p[3 * id + 1] - y,
            dz = p[3 * id + 2] - z;
          const d = dx * dx + dy * dy + dz * dz;
          if (found === k && (d > worst || (d === worst && id > outIds[k - 1]))) continue;
          // Insertion into the sorted prefix.
          let s = found < k ? found++ : k - 1;
          while (s > 0 && (outD2[s - 1] > d || (outD2[s - 1] === d && outIds[s - 1] > id))) {
            outD2[s] = outD2[s - 1];
            outIds[s] = outIds[s - 1];
            s--;
          }
          outD2[s] = d;
          outIds[s] = id;
          if (found === k) worst = outD2[k - 1];
        }
        continue;
      }
      const diff = (ax === 0 ? x : ax === 1 ? y : z) - this.split[node];
      const near = diff < 0 ? this.left[node] : this.right[node];
      const far = diff < 0 ? this.right[node] : this.left[node];
      // Far child pushed first so that the near one is popped first.
      if (top + 2 > this.stack.length) throw new Error('KdTree3: stack overflow (degenerate points)');
      this.stack[top] = far;
      this.stackD[top++] = diff * diff;
      this.stack[top] = near;
      this.stackD[top++] = 0;
    }
    return found;
  }

  /** Id of the nearest point (ties by id); -1 when empty. */
  nearest(x: number, y: number, z: number, ids: Int32Array, d2: Float64Array): number {
    return this.knn(x, y, z, 1, ids, d2) > 0 ? ids[0] : -1;
  }
}
