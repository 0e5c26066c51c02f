/**
 * The one border convention of every adjacency record (`SurfaceAdjacency.border`, in
 * src/core/analysis/adjacency.ts): per cell, a bit mask of why the cell is not whole on that
 * surface. 0 is an interior cell. Any bit makes it a border cell: excluded from the statistics,
 * still a neighbour of others.
 *
 * The four edge bits say which open edges of the domain the cell touches. y runs along the rows
 * (a tube's axis, whose ends are its open edges; an image's top row is y = 0), x along the
 * columns (around a tube: periodic, never a border). A closed surface has no open edge.
 * `BORDER_EXCLUDED` marks a cell left out for another reason: a measured cell missing from a
 * layer or cut by the image's bounds, or a cell the lab protocol excludes over the stack.
 */
export const BORDER_Y_START = 1;
export const BORDER_Y_END = 2;
export const BORDER_X_START = 4;
export const BORDER_X_END = 8;
export const BORDER_EXCLUDED = 16;
