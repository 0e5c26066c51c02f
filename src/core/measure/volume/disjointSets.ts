/**
 * Disjoint sets of 0 .. n - 1, each its own set at first: `parent` (a root is its own parent;
 * join two sets by pointing one root at the other) and `find` (the root, halving the path).
 */
export function disjointSets(n: number): { parent: Int32Array; find: (i: number) => number } {
  const parent = new Int32Array(n);
  for (let i = 0; i < n; i++) parent[i] = i;
  const find = (i: number): number => {
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  return { parent, find };
}
