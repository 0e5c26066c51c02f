/** Measuring segmented label images of a real tissue beside the model (docs/measure.md). */
export * from './errors';
export * from './labelImage';
export * from './pixelSize';
export * from './decodePng';
export * from './decodeTiff';
export * from './contacts';
export * from './layerPlan';
export * from './measuredResult';
export * from './measureTissue';
export * from './compare';
export * from './compareMeasured';
export * from './volume';
