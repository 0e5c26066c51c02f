/** Measuring a 3D label volume of a curved epithelium (docs/measure.md, "Measuring a volume"). */
export * from './tiffPages';
export * from './tiffVolume';
export * from './lzw';
export * from './voxelSize';
export * from './voxelClasses';
export * from './faceScan';
export * from './contactEdges';
export * from './curveLength';
export * from './quartets';
export * from './volumeResult';
export * from './measureVolume';
export * from './compareVolume';
export * from './surfaceMesh';
export * from './meshModel';
export * from './tubeFit';
export * from './modelDrawing';
