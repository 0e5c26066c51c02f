/**
 * The page's pipeline worker (see pageRunner.ts): the pipeline (servePipeline), and the views'
 * pictures of each result drawn here when a run asks (workerPictures.ts), so the page's main
 * thread only uploads them.
 */
import { servePipeline } from '../run/worker/servePipeline';
import { drawPictures, isPictureRequest } from './workerPictures';

servePipeline((output, options) => (isPictureRequest(options) ? drawPictures(output, options) : { presented: undefined, transfer: [] }));
