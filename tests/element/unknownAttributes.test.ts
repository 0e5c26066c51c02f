import { describe, expect, it } from 'vitest';
import { createRandom } from '../../src/core/random';
import { unknownAttributes } from '../../src/element/unknownAttributes';

/**
 * The element's unknown-attribute warnings: global HTML attributes and known ones pass, every
 * other one is named, and its suggestion is a nearest known name within two edits, checked
 * against an edit distance written here from its recursive definition.
 */

const KNOWN = ['cells', 'seed', 'surface', 'surface-ratio', 'thickness', 'resolution', 'realizations', 'manual'];

/** Levenshtein distance from its definition (memoised recursion), independent of the element's. */
function distance(a: string, b: string): number {
  const memo = new Map<string, number>();
  const d = (i: number, j: number): number => {
    if (i === 0) return j;
    if (j === 0) return i;
    const key = `${i},${j}`;
    if (!memo.has(key)) memo.set(key, Math.min(d(i - 1, j) + 1, d(i, j - 1) + 1, d(i - 1, j - 1) + (a[i - 1] === b[j - 1] ? 0 : 1)));
    return memo.get(key)!;
  };
  return d(a.length, b.length);
}

describe('unknownAttributes', () => {
  it('passes known and global attributes', () => {
    const names = ['cells', 'id', 'class', 'style', 'data-anything', 'aria-label', 'onclick', 'slot', 'hidden', 'manual'];
    expect(unknownAttributes(names, KNOWN)).toEqual([]);
  });

  it('names a typo with the attribute meant, and a far name without a suggestion', () => {
    const [typo, far] = unknownAttributes(['cels', 'background-colour'], KNOWN);
    expect(typo).toEqual({ attribute: 'cels', suggestion: 'cells', message: 'unknown attribute "cels" ignored (did you mean "cells"?)' });
    expect(far).toEqual({ attribute: 'background-colour', message: 'unknown attribute "background-colour" ignored' });
  });

  it('suggests a nearest known name within two edits, and none when every one is farther', () => {
    const random = createRandom(25);
    const next = () => random.next();
    const letters = 'acdeilmnorstuz-';
    for (let trial = 0; trial < 400; trial++) {
      // A known name with 0 to 4 random edits, or a random word.
      let name = trial % 5 === 0 ? '' : KNOWN[Math.floor(next() * KNOWN.length)];
      const edits = trial % 5 === 0 ? 3 + Math.floor(next() * 6) : Math.floor(next() * 5);
      for (let e = 0; e < edits; e++) {
        const at = Math.floor(next() * (name.length + 1));
        const letter = letters[Math.floor(next() * letters.length)];
        const kind = next();
        name =
          kind < 0.4
            ? name.slice(0, at) + letter + name.slice(at)
            : kind < 0.7
              ? name.slice(0, at) + name.slice(at + 1)
              : name.slice(0, at) + letter + name.slice(at + 1);
      }
      if (name === '' || KNOWN.includes(name) || /^(on[a-z]+|is|id|dir|lang|role|part|slot)$/.test(name)) continue;
      const [warning] = unknownAttributes([name], KNOWN);
      expect(warning.attribute).toBe(name);
      const nearest = Math.min(...KNOWN.map((k) => distance(name, k)));
      if (nearest <= 2) {
        expect(warning.suggestion, name).toBeDefined();
        expect(distance(name, warning.suggestion!)).toBe(nearest);
      } else {
        expect(warning.suggestion, name).toBeUndefined();
      }
    }
  });
});
