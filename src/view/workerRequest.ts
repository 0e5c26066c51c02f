/**
 * One request to a page worker whose replies carry the request's id (the measuring, volume and
 * result-opening workers): listens until `handle` finishes it; fails it when a newer request was
 * made since (its late replies are not handled); and when the worker dies (an error event, e.g.
 * out of memory) terminates it and fails the request, after `onCrash` (where the client forgets
 * the worker, so that its next request starts a fresh one).
 */
export interface WorkerRequest<Reply> {
  worker: Worker;
  id: number;
  message: unknown;
  transfer?: Transferable[];
  /** Whether this request is still the client's latest. */
  isLatest(): boolean;
  /** The error of a request superseded by a newer one. */
  superseded(): Error;
  /** The error of a request whose worker stopped (`details`: the event's message, or why there is none). */
  crashed(details: string): Error;
  onCrash(): void;
  /** Each reply to this request, in order; `finish.done()` or `finish.fail(error)` ends it. */
  handle(reply: Reply, finish: RequestFinish): void;
}

interface RequestFinish {
  done(): void;
  fail(error: Error): void;
}

export function requestWorker<Reply extends { id: number }>(request: WorkerRequest<Reply>): Promise<void> {
  const { worker } = request;
  return new Promise<void>((resolve, reject) => {
    const stop = () => {
      worker.removeEventListener('message', listen);
      worker.removeEventListener('error', crashed);
    };
    const finish: RequestFinish = {
      done: () => {
        stop();
        resolve();
      },
      fail: (error) => {
        stop();
        reject(error);
      },
    };
    const listen = (event: MessageEvent<Reply>) => {
      if (event.data.id !== request.id) return;
      if (!request.isLatest()) finish.fail(request.superseded());
      else request.handle(event.data, finish);
    };
    const crashed = (event: ErrorEvent) => {
      event.preventDefault();
      worker.terminate();
      request.onCrash();
      finish.fail(request.crashed(event.message || 'no details; perhaps out of memory'));
    };
    worker.addEventListener('message', listen);
    worker.addEventListener('error', crashed);
    worker.postMessage(request.message, request.transfer ?? []);
  });
}
