/**
 * An exclusive lock on a sweep's output directory: a file created with O_EXCL holding the
 * owner's pid, host and start time. A second sweep on the same directory is refused, naming
 * the holder; a lock left by a process that no longer runs (same host) is taken over with a
 * warning.
 */
import { hostname } from 'node:os';
import { openSync, readFileSync, rmSync, writeSync, closeSync } from 'node:fs';
import { join } from 'node:path';
import { EnvironmentError } from './errors';

export const LOCK_NAME = '.tissue-sheet.lock';

interface LockInfo {
  pid: number;
  host: string;
  started: string;
}

function alive(pid: number): boolean {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return (error as NodeJS.ErrnoException).code === 'EPERM';
  }
}

/** Takes the lock of `dir`; returns its release function. */
export function lockDirectory(dir: string, warn: (line: string) => void): () => void {
  const path = join(dir, LOCK_NAME);
  const info: LockInfo = { pid: process.pid, host: hostname(), started: new Date().toISOString() };
  for (let attempt = 0; attempt < 2; attempt++) {
    let fd: number;
    try {
      fd = openSync(path, 'wx');
    } catch (error) {
      if ((error as NodeJS.ErrnoException).code !== 'EEXIST') throw new EnvironmentError(`${path}: cannot create the lock file (${(error as Error).message})`);
      let holder: Partial<LockInfo> = {};
      try {
        holder = JSON.parse(readFileSync(path, 'utf8')) as LockInfo;
      } catch {
        // unreadable: treated as held
      }
      if (holder.host === info.host && typeof holder.pid === 'number' && !alive(holder.pid)) {
        warn(`warning: ${path}: taking over the lock of process ${holder.pid}, which no longer runs`);
        rmSync(path, { force: true });
        continue;
      }
      throw new EnvironmentError(
        `${dir}: another sweep is writing here (process ${holder.pid ?? '?'} on ${holder.host ?? '?'}, since ${holder.started ?? '?'}); wait for it, or remove ${path} if that process is gone`,
      );
    }
    writeSync(fd, JSON.stringify(info) + '\n');
    closeSync(fd);
    let released = false;
    const release = () => {
      if (released) return;
      released = true;
      try {
        const current = JSON.parse(readFileSync(path, 'utf8')) as LockInfo;
        if (current.pid === info.pid && current.host === info.host) rmSync(path, { force: true });
      } catch {
        // already gone
      }
    };
    process.once('exit', release);
    return release;
  }
  throw new EnvironmentError(`${path}: cannot take the lock`);
}
