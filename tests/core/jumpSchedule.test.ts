import { describe, expect, it } from 'vitest';
import { cubeFaceHops } from '../../src/core/cubemap/cubemap';
import { coldSchedule, FloodSchedules, nextPowerOfTwo, warmFirstStep, warmSchedule } from '../../src/core/jumpSchedule';

describe('jump flood schedules', () => {
  it('halves from half the next power of two of the larger side', () => {
    expect(coldSchedule(300, 200, 'jfa')).toEqual([256, 128, 64, 32, 16, 8, 4, 2, 1]);
    expect(coldSchedule(300, 200, 'jfa+2').slice(-3)).toEqual([1, 2, 1]);
    expect(coldSchedule(300, 200, '1+jfa').slice(0, 2)).toEqual([1, 256]);
    expect(coldSchedule(1, 1, 'jfa')).toEqual([1]);
  });
  it('starts a warm flood with steps that reach the largest displacement, then one extra step 1', () => {
    expect(warmSchedule(512, 512, 0)).toEqual([1]);
    expect(warmSchedule(512, 512, 0.4)).toEqual([2, 1]);
    expect(warmSchedule(512, 512, 3)).toEqual([4, 2, 1]);
    expect(warmSchedule(512, 512, 10)).toEqual([8, 4, 2, 1]);
    expect(warmSchedule(64, 64, 1000)[0]).toBe(32);
    expect(warmFirstStep(512, 512, 3)).toBe(warmSchedule(512, 512, 3)[0]);
  });
  it('rounds up to powers of two', () => {
    expect([1, 2, 3, 1000, 1024].map(nextPowerOfTwo)).toEqual([1, 2, 4, 1024, 1024]);
  });
});

describe('FloodSchedules (both GPU engines)', () => {
  it('gives the cold schedule and each warm schedule, built once per first step (a Lloyd loop allocates none)', () => {
    const schedules = new FloodSchedules(256, 96, 'jfa+2');
    expect(schedules.steps()).toEqual(coldSchedule(256, 96, 'jfa+2'));
    for (const moved of [0, 0.4, 3, 7.9, 40, 1e6]) {
      const steps = schedules.steps(moved);
      expect(steps).toEqual(warmSchedule(256, 96, moved));
      expect(schedules.steps(moved)).toBe(steps); // the same array, not a copy
    }
    // displacements with the same first step share one schedule
    expect(schedules.steps(5)).toBe(schedules.steps(6));
  });
});

describe('face hops of a cold cube-map flood (few sites)', () => {
  const n = 8;
  // Site data as the engine holds it: x, y, z, atlas index; face f's texels are f n² .. (f + 1) n² - 1.
  const onFaces = (...faces: number[]) => faces.flatMap((f) => [0, 0, 0, f * n * n + 5]);
  it('needs none with a site on every face, one when several faces hold sites, two when one face holds them all', () => {
    expect(cubeFaceHops(n, onFaces(0, 1, 2, 3, 4, 5, 5), 7)).toBe(0);
    for (const faces of [
      [0, 1],
      [2, 3],
      [4, 0, 0],
      [0, 1, 2, 3, 4],
    ])
      expect(cubeFaceHops(n, onFaces(...faces), faces.length)).toBe(1);
    for (const faces of [[0], [5], [3, 3, 3]]) expect(cubeFaceHops(n, onFaces(...faces), faces.length)).toBe(2);
  });
  it('prefixes the cold schedule with that many steps of the whole side; warm schedules have none', () => {
    const schedules = new FloodSchedules(24, 24, 'jfa+2');
    expect(schedules.steps(undefined, 0)).toBe(schedules.cold);
    expect(schedules.steps(undefined, 1)).toEqual([24, ...schedules.cold]);
    expect(schedules.steps(undefined, 2)).toEqual([24, 24, ...schedules.cold]);
    expect(schedules.steps(3, 2)).toEqual(warmSchedule(24, 24, 3));
  });
});
