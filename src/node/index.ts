/**
 * `tissue-sheet/node`: what only Node has. A WebGL2 context from headless-gl (the optional `gl`
 * dependency, loaded when a context is first asked for) and PNG density images read from disk.
 * Pair it with the pipeline from the main entry:
 *
 *   import { runSheet, validateConfig } from 'tissue-sheet';
 *   import { createHeadlessContext } from 'tissue-sheet/node';
 */
export { createHeadlessContext, headlessRendererName } from './headless';
export { decodeGrayPng, loadGrayImage } from './image';
export { loadMeshFile } from './meshFile';
export { readResultFile, type ResultFile } from './resultFile';
