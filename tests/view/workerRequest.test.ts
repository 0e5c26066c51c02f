import { describe, expect, it } from 'vitest';
import { requestWorker, type WorkerRequest } from '../../src/view/workerRequest';

/** A worker stand-in: records what it was sent and lets the test reply or crash. */
class FakeWorker extends EventTarget {
  sent: unknown[] = [];
  terminated = false;
  postMessage(message: unknown): void {
    this.sent.push(message);
  }
  terminate(): void {
    this.terminated = true;
  }
  reply(data: { id: number; type: string }): void {
    this.dispatchEvent(Object.assign(new Event('message'), { data }));
  }
  crash(message: string): void {
    this.dispatchEvent(Object.assign(new Event('error', { cancelable: true }), { message }));
  }
}

type Reply = { id: number; type: string };

function request(worker: FakeWorker, id: number, latest: () => number, seen: string[], crashes: number[]): WorkerRequest<Reply> {
  return {
    worker: worker as unknown as Worker,
    id,
    message: { id },
    isLatest: () => latest() === id,
    superseded: () => new Error(`${id} superseded`),
    crashed: (details) => new Error(`${id} crashed: ${details}`),
    onCrash: () => crashes.push(id),
    handle: (reply, finish) => {
      seen.push(`${reply.id}:${reply.type}`);
      if (reply.type === 'done') finish.done();
      else if (reply.type === 'error') finish.fail(new Error('worker said no'));
    },
  };
}

describe('requestWorker', () => {
  it('hands this request its own replies in order until done, and stops listening', async () => {
    const worker = new FakeWorker();
    const seen: string[] = [];
    const pending = requestWorker(request(worker, 1, () => 1, seen, []));
    expect(worker.sent).toEqual([{ id: 1 }]);
    worker.reply({ id: 2, type: 'progress' }); // another request's reply: ignored
    worker.reply({ id: 1, type: 'progress' });
    worker.reply({ id: 1, type: 'done' });
    await expect(pending).resolves.toBeUndefined();
    worker.reply({ id: 1, type: 'late' });
    expect(seen).toEqual(['1:progress', '1:done']);
  });

  it('fails a request superseded by a newer one at its next reply', async () => {
    const worker = new FakeWorker();
    let latest = 1;
    const seen: string[] = [];
    const pending = requestWorker(request(worker, 1, () => latest, seen, []));
    latest = 2;
    worker.reply({ id: 1, type: 'progress' });
    await expect(pending).rejects.toThrow('1 superseded');
    expect(seen).toEqual([]);
  });

  it("passes the handler's failure on", async () => {
    const worker = new FakeWorker();
    const pending = requestWorker(request(worker, 3, () => 3, [], []));
    worker.reply({ id: 3, type: 'error' });
    await expect(pending).rejects.toThrow('worker said no');
  });

  it('a worker that dies is terminated, forgotten and fails the request with its message', async () => {
    const worker = new FakeWorker();
    const crashes: number[] = [];
    const pending = requestWorker(request(worker, 4, () => 4, [], crashes));
    worker.crash('out of memory');
    await expect(pending).rejects.toThrow('4 crashed: out of memory');
    expect(worker.terminated).toBe(true);
    expect(crashes).toEqual([4]);
    const silent = new FakeWorker();
    const second = requestWorker(request(silent, 5, () => 5, [], []));
    silent.crash('');
    await expect(second).rejects.toThrow('5 crashed: no details; perhaps out of memory');
  });
});
