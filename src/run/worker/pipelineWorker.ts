/**
 * The pipeline in a Web Worker (servePipeline.ts): the page only draws. This entry sends results
 * as they are; the view's worker (src/view/viewWorker.ts) also paints the label images here.
 */
import { servePipeline } from './servePipeline';

servePipeline();
