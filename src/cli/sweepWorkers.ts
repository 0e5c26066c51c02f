/**
 * Worker threads for `tissue-sheet sweep --workers N` (N - 1 of them: the main thread computes
 * runs too, whenever it is free and every thread is busy): each thread keeps its own SheetRunner
 * (so it reuses a seeded surface for every `sheet.*` value and one Lloyd run for every Voronoi k
 * it is given) and computes whole tasks (a task: the runs sharing a seeded surface), sending each
 * run's summary back as it finishes. The main thread writes the rows in the sweep's order (see
 * runSweep), so the files do not depend on N or on which thread finishes first.
 *
 * Only runs on the exact CPU engine go to threads: headless-gl is a native module that loads in
 * one thread of a process only (a second gets "Module did not self-register"), so GPU runs stay
 * on the main thread's context. A thread gets the main context's capabilities, from which the
 * engine policy picks the same engine as it does there; a thread never opens a GL context.
 *
 * This module is also the threads' entry: a thread loads it (from the compiled bundle, or from
 * the sources through tsx's loader when the CLI runs from TypeScript) and the code at the end
 * starts the thread's loop when it finds its workerData.
 */
import { isMainThread, parentPort, type Worker, workerData } from 'node:worker_threads';
import { validateConfig } from '../core/config';
import { flatList } from '../core/sweep';
import type { FlintstonesPoint } from '../core/analysis/flintstones';
import type { GpuCapabilities } from '../gpu/context';
import { SheetRunner } from '../run/index';
import { FlatSummaries } from './flatSummaries';
import type { RunInputs } from './prepare';
import { fitOutcome, type FitOutcome } from '../core/sweep/fitOutcomes';
import { capabilitiesOnly, deserializeError, newThread, serializeError, tuneJitForThreads, type SerializedError } from './threads';

export { defaultWorkers } from './threads';

/** One run as a thread receives it. */
export interface WorkerRun {
  readonly key: string;
  readonly pointKey: string;
  readonly config: unknown;
}

/** What a thread needs before its first task: the main context's capabilities and the density images. */
interface WorkerSetup {
  readonly capabilities: GpuCapabilities;
  readonly inputs: [string, RunInputs][];
}

/** A thread's workerData: it is a sweep thread; its setup comes as its first message. */
interface WorkerMark {
  readonly tissueSheetSweepWorker: true;
}

type ToWorker =
  | { type: 'setup'; setup: WorkerSetup }
  | { type: 'task'; id: number; runs: WorkerRun[] }
  /** Fits taken from `problems` one at a time by every thread, the next index from the shared counter. */
  | { type: 'fits'; id: number; problems: readonly (readonly FlintstonesPoint[])[]; counter: SharedArrayBuffer }
  | { type: 'abort' };
type FromWorker =
  /**
   * A run's summary, flattened (flattenSummary): its values, and the number of its key list
   * (each distinct list is sent once per thread, with the first run that has it).
   */
  | DoneMessage
  /**
   * The summaries of a task's runs, in the order they finished, in one message (fewer messages
   * cost less than many); `finished`: the task ended with them (no 'finished' message follows).
   */
  | { type: 'dones'; id: number; items: PackedDone[]; numbers: Float64Array; finished: boolean }
  | { type: 'failed'; id: number; error: SerializedError }
  /** A Flintstones fit (core/sweep/fitOutcomes.ts). */
  | { type: 'fitted'; id: number; outcome: FitOutcome; index: number }
  /** A thread found no fit of a `fits` message left to take. */
  | { type: 'fitsDone'; id: number }
  | { type: 'finished'; id: number };
type DoneMessage = { type: 'done'; id: number; key: string; layout: number; keys?: string[]; numbers: Float64Array; others: [number, unknown][] };
/** A run's summary in a task's message: its numbers are `length` values from `at` in the message's one array. */
type PackedDone = Omit<DoneMessage, 'numbers'> & { at: number; length: number };

/** A thread failed or exited under a task: its runs not reported yet can be computed elsewhere. */
export class SweepThreadLost extends Error {
  override readonly name = 'SweepThreadLost';
}

interface Slot {
  readonly worker: Worker;
  /** The affinity (e.g. the Lloyd run) of the last task it computed. */
  affinity: string | null;
  /** Unused: set on a thread that failed to start or exited. */
  reserved: boolean;
  /** The summary key lists the thread has sent, by number. */
  readonly layouts: Map<number, string[]>;
  /** Its tasks sent and not finished, by message id (at most TASKS_PER_THREAD, in the order sent). */
  readonly tasks: Map<number, PendingTask>;
}

interface PendingTask {
  done: (key: string, summary: unknown) => void;
  resolve: (value?: unknown) => void;
  reject: (error: unknown) => void;
}

/**
 * Tasks a thread holds at once: the one it computes and the next, queued in the thread. With
 * one, a thread idled between tasks while its result crossed to this thread and the next task
 * came back (1-5 ms, 200 times in the published grid's sweep).
 */
const TASKS_PER_THREAD = 2;

/** A pool of sweep threads; `run` sends a task to a free one (callers never exceed `size` at once). */
export class SweepWorkers {
  private readonly slots: Slot[] = [];
  private waiting: (() => void)[] = [];
  private nextId = 1;
  private closed = false;
  /** fitMany's batches by message id: the outcomes so far and the threads still taking fits. */
  private readonly batches = new Map<number, { outcomes: (FitOutcome | null)[]; waiting: Set<Slot>; resolve: () => void }>();

  /**
   * `size` threads; with `capabilities` they are set up at once, else `setUp` must be called
   * before any task (the threads load their modules meanwhile: the sweep starts them before it
   * opens its GL context and checks the grid, which the capabilities come from).
   */
  constructor(size: number, capabilities?: GpuCapabilities, inputs: Map<string, RunInputs> = new Map()) {
    const mark: WorkerMark = { tissueSheetSweepWorker: true };
    tuneJitForThreads(size, true);
    for (let k = 0; k < size; k++) {
      const worker = newThread(import.meta.url, mark);
      const slot: Slot = { worker, affinity: null, reserved: false, layouts: new Map(), tasks: new Map() };
      worker.on('message', (message: FromWorker) => this.receive(slot, message));
      worker.on('error', (error) =>
        this.lost(slot, new SweepThreadLost(`a sweep worker thread failed: ${error instanceof Error ? error.message : String(error)}`)),
      );
      worker.on('exit', (code) => {
        if (!this.closed && this.slots.includes(slot)) this.lost(slot, new SweepThreadLost(`a sweep worker thread exited (code ${code})`));
      });
      this.slots.push(slot);
    }
    if (capabilities) this.setUp(capabilities, inputs);
  }

  /** Gives every thread the main context's capabilities and the density images (once, before any task). */
  setUp(capabilities: GpuCapabilities, inputs: Map<string, RunInputs>): void {
    const setup: WorkerSetup = {
      capabilities: { ...capabilities },
      // Threads only run planes and tubes (exact engine): no mesh crosses.
      inputs: [...inputs].map(([key, value]) => [key, value.densityImage ? { densityImage: value.densityImage } : {}]),
    };
    for (const slot of this.slots) slot.worker.postMessage({ type: 'setup', setup } satisfies ToWorker);
  }

  /** Keeps `size` threads (started before the sweep knew how many it needs), ending the others. */
  async shrink(size: number): Promise<void> {
    const extra = this.slots.splice(Math.max(0, size));
    await Promise.all(extra.map((slot) => slot.worker.terminate()));
  }

  /** False once every thread failed or exited (the caller then computes on its own thread). */
  get usable(): boolean {
    return this.slots.some((s) => !s.reserved);
  }

  /** Whether some thread has no task (one that fails or exited does not count). */
  get hasIdleThread(): boolean {
    return this.slots.some((s) => s.tasks.size === 0 && !s.reserved);
  }

  /** Tasks the pool takes at once (callers may keep this many running). */
  get capacity(): number {
    return this.slots.length * TASKS_PER_THREAD;
  }

  /**
   * Computes `runs` in one thread: an idle one first, and among those one whose last task had
   * the same `affinity` (it still holds that Lloyd run); else queued behind the task of a busy
   * one. `done` gets each run's summary as it finishes.
   */
  async run(runs: WorkerRun[], affinity: string, done: (key: string, summary: unknown) => void): Promise<void> {
    const pick = (free: Slot[]) => {
      const idle = free.filter((s) => s.tasks.size === 0);
      const among = idle.length > 0 ? idle : free;
      return among.find((s) => s.affinity === affinity) ?? among.find((s) => s.affinity === null) ?? among[0];
    };
    // Taken at once where a thread has room (no await before the task is added: a caller asking
    // right after sees the thread busy), else once one has.
    const slot = this.withRoom(pick) ?? (await this.claim(pick));
    slot.affinity = affinity;
    const id = this.nextId++;
    return new Promise<void>((resolve, reject) => {
      slot.tasks.set(id, { done, resolve: () => resolve(), reject });
      slot.worker.postMessage({ type: 'task', id, runs } satisfies ToWorker);
    });
  }

  /**
   * Fits every problem on the threads, each thread taking the next one left as it gets free (a
   * counter they share: fits differ a lot in cost, a few of them do not converge and take most
   * of the time, so fits dealt out in turn left one thread with the slow ones). Every request
   * goes out at once, queued behind what a thread is doing: the main thread computes the
   * aggregate meanwhile. Null for a problem no thread fitted (a thread lost: the caller fits it).
   * At most `threads` threads take part (the main thread's aggregate needs a core too).
   */
  fitMany(problems: readonly (readonly FlintstonesPoint[])[], threads = this.slots.length): Promise<(FitOutcome | null)[]> {
    const outcomes: (FitOutcome | null)[] = problems.map(() => null);
    const live = this.slots.filter((s) => !s.reserved).slice(0, Math.max(1, threads));
    if (live.length === 0 || problems.length === 0) return Promise.resolve(outcomes);
    const id = this.nextId++;
    const counter = new SharedArrayBuffer(4);
    return new Promise((resolve) => {
      this.batches.set(id, { outcomes, waiting: new Set(live), resolve: () => resolve(outcomes) });
      for (const slot of live) slot.worker.postMessage({ type: 'fits', id, problems, counter } satisfies ToWorker);
    });
  }

  /**
   * A thread with room for a task, chosen by `pick`, once there is one (callers may ask for more
   * at once than the threads hold). The caller adds its task before it awaits anything.
   */
  private async claim(pick: (free: Slot[]) => Slot): Promise<Slot> {
    for (;;) {
      const slot = this.withRoom(pick);
      if (slot) return slot;
      if (this.slots.every((s) => s.reserved)) throw new SweepThreadLost('no sweep worker thread is left (they failed or exited)');
      await new Promise<void>((wake) => this.waiting.push(wake));
    }
  }

  /** A thread with room for a task, chosen by `pick`; null when none has. */
  private withRoom(pick: (free: Slot[]) => Slot): Slot | null {
    const free = this.slots.filter((s) => s.tasks.size < TASKS_PER_THREAD && !s.reserved);
    return free.length > 0 ? pick(free) : null;
  }

  /** Asks every thread to stop its task at the next iteration (the task then fails with an AbortError). */
  abort(): void {
    for (const slot of this.slots) slot.worker.postMessage({ type: 'abort' } satisfies ToWorker);
  }

  async close(): Promise<void> {
    this.closed = true;
    await Promise.all(this.slots.map((slot) => slot.worker.terminate()));
  }

  /** Task `id` of `slot` ended: a caller waiting for room may go on. */
  private release(slot: Slot, id: number): void {
    slot.tasks.delete(id);
    const wake = this.waiting.shift();
    wake?.();
  }

  /** Ends every task `slot` holds with `error` and takes the thread out of use. */
  private retire(slot: Slot, error: unknown): void {
    slot.reserved = true;
    const tasks = [...slot.tasks.values()];
    slot.tasks.clear();
    for (const wake of this.waiting.splice(0)) wake();
    for (const task of tasks) task.reject(error);
  }

  private receive(slot: Slot, message: FromWorker): void {
    if (message.type === 'dones') {
      for (const { at, length, ...item } of message.items) this.receive(slot, { ...item, numbers: message.numbers.subarray(at, at + length) });
      if (message.finished) this.receive(slot, { type: 'finished', id: message.id });
      return;
    }
    if (message.type === 'done' && message.keys) slot.layouts.set(message.layout, message.keys);
    const batch = message.type === 'fitted' || message.type === 'fitsDone' ? this.batches.get(message.id) : undefined;
    if (batch) {
      if (message.type === 'fitted') batch.outcomes[message.index] = message.outcome;
      else if (message.type === 'fitsDone') this.doneWithBatch(message.id, slot);
      return;
    }
    // A fit of a batch that ended (its thread was counted lost): nobody waits for it.
    if (message.type === 'fitted' || message.type === 'fitsDone') return;
    const current = slot.tasks.get(message.id);
    if (!current) return;
    if (message.type === 'done') {
      try {
        const keys = slot.layouts.get(message.layout);
        if (!keys || keys.length !== message.numbers.length) throw new Error('a sweep worker thread sent a summary without its keys');
        const values: unknown[] = Array.from(message.numbers);
        for (const [k, value] of message.others) values[k] = value;
        // Already flat, as its key list and values: the row is made from them as they are
        // (no object of hundreds of keys per run).
        current.done(message.key, flatList(keys, values));
      } catch (error) {
        // The thread goes on with its tasks; its messages for them are ignored from now on.
        this.retire(slot, error);
      }
    } else if (message.type === 'failed') {
      this.release(slot, message.id);
      current.reject(deserializeError(message.error));
    } else {
      this.release(slot, message.id);
      current.resolve();
    }
  }

  /** `slot` takes no more fits of batch `id`; the batch ends when no thread does. */
  private doneWithBatch(id: number, slot: Slot): void {
    const batch = this.batches.get(id);
    if (!batch) return;
    batch.waiting.delete(slot);
    if (batch.waiting.size > 0) return;
    this.batches.delete(id);
    batch.resolve();
  }

  private lost(slot: Slot, error: unknown): void {
    for (const id of [...this.batches.keys()]) this.doneWithBatch(id, slot);
    this.retire(slot, error);
  }
}

/** The thread's loop: its setup first, then tasks one at a time, each run's summary sent as it finishes. */
function startWorker(): void {
  const port = parentPort!;
  let runner: SheetRunner | null = null;
  let inputs = new Map<string, RunInputs>();
  let controller = new AbortController();
  /** Tasks with an id up to this one were sent before an abort: they fail, queued ones too. */
  let abortedThrough = 0;
  let lastTask = 0;
  /** Run summaries flattened (the keys of each shape sent once: `layout`). */
  const summaries = new FlatSummaries();
  let queue: Promise<void> = Promise.resolve();
  const send = (message: FromWorker) => port.postMessage(message);
  port.on('message', (message: ToWorker) => {
    if (message.type === 'setup') {
      runner = new SheetRunner(capabilitiesOnly(message.setup.capabilities));
      inputs = new Map(message.setup.inputs);
      return;
    }
    if (message.type === 'abort') {
      abortedThrough = lastTask;
      controller.abort();
      return;
    }
    if (message.type === 'fits') {
      const { id, problems } = message;
      const next = new Int32Array(message.counter);
      queue = queue.then(() => {
        for (let k = Atomics.add(next, 0, 1); k < problems.length; k = Atomics.add(next, 0, 1)) {
          send({ type: 'fitted', id, index: k, outcome: fitOutcome(problems[k]) });
        }
        send({ type: 'fitsDone', id });
      });
      return;
    }
    const { id, runs } = message;
    lastTask = id;
    queue = queue.then(async () => {
      if (controller.signal.aborted && id > abortedThrough) controller = new AbortController();
      const { signal } = controller;
      try {
        const sheets = runner;
        if (!sheets) throw new Error('a sweep worker thread got a task before its setup');
        signal.throwIfAborted();
        // Fewer Lloyd iterations first: one Lloyd run then serves every Voronoi k of the task.
        const order = runs.map((run, k) => ({ run, k, config: validateConfig(run.config) }));
        order.sort((a, b) => a.config.lloyd.maxIterations - b.config.lloyd.maxIterations || a.k - b.k);
        // A task's summaries go out together when it ends, or as they are when it fails.
        const batch: DoneMessage[] = [];
        const flush = (finished: boolean) => {
          if (batch.length === 0) {
            if (finished) send({ type: 'finished', id });
          } else {
            // All the numbers in one transferred array (one per run cost more to send).
            const numbers = new Float64Array(batch.reduce((n, item) => n + item.numbers.length, 0));
            let at = 0;
            const items = batch.map(({ numbers: own, ...item }): PackedDone => {
              numbers.set(own, at);
              at += own.length;
              return { ...item, at: at - own.length, length: own.length };
            });
            port.postMessage({ type: 'dones', id, items, numbers, finished } satisfies FromWorker, [numbers.buffer]);
          }
          batch.length = 0;
        };
        try {
          for (const { run, config } of order) {
            const output = await sheets.run(config, { ...inputs.get(run.pointKey), signal, views: false });
            const { layout, keys, known, values } = summaries.of(output.result);
            // Numbers in a transferred Float64Array (cloning a list of values costs per value), the rest apart.
            const numbers = new Float64Array(keys.length);
            const others: [number, unknown][] = [];
            values.forEach((value, n) => {
              if (typeof value === 'number') numbers[n] = value;
              else others.push([n, value]);
            });
            batch.push({ type: 'done', id, key: run.key, layout, ...(known ? {} : { keys }), numbers, others });
          }
        } catch (error) {
          flush(false);
          throw error;
        }
        flush(true);
      } catch (error) {
        send({ type: 'failed', id, error: serializeError(error) });
      }
    });
  });
}

if (!isMainThread && (workerData as Partial<WorkerMark> | null)?.tissueSheetSweepWorker === true) startWorker();
