/**
 * How large an input file any host (the CLI, the page, the worker, the Node library) reads: one
 * set of limits, checked before a file is read or decoded (a file's size first, an image's
 * header before its pixels).
 */

/** A mesh file (OBJ, PLY, STL): bytes at most. */
export const MAX_MESH_BYTES = 256 * 2 ** 20;
/** A density PNG: bytes at most. */
export const MAX_PNG_BYTES = 256 * 2 ** 20;
/** A density PNG: pixels at most, read from its header before decoding. */
export const MAX_IMAGE_PIXELS = 8192 * 8192;
