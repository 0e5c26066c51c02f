/**
 * Which open edges of a domain a cell touches, as a bit mask: the one convention of every
 * adjacency (label images, the exact planar diagram, measured images). y runs along the rows
 * (a tube's axis, whose ends are its open edges; an image's top row is y = 0), x along the
 * columns (around a tube: periodic, never a border). A cell touching any open edge is a border
 * cell: excluded from the statistics, still a neighbour of others.
 */
export const BORDER_Y_START = 1;
export const BORDER_Y_END = 2;
export const BORDER_X_START = 4;
export const BORDER_X_END = 8;
