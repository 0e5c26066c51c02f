/**
 * Attributes the element does not know are said, never ignored silently: each one becomes a
 * warning naming it, with the nearest known attribute when one is close (a typo such as
 * `cels` for `cells`). Global HTML attributes (`id`, `class`, `data-*`, `aria-*`, `on*`, ...)
 * are not the element's to judge and pass.
 */

/** One unknown attribute: the warning in words, and the attribute the user probably meant. */
export interface UnknownAttribute {
  readonly message: string;
  readonly attribute: string;
  readonly suggestion?: string;
}

const GLOBAL_ATTRIBUTE =
  /^(id|class|style|title|slot|hidden|lang|dir|tabindex|part|role|is|draggable|translate|inert|autofocus|contenteditable|spellcheck|nonce|exportparts|popover|accesskey|enterkeyhint|inputmode|(data|aria)-.+|on[a-z]+)$/;

/** The warnings for the attribute `names` that are neither `known` nor global, in order. */
export function unknownAttributes(names: readonly string[], known: readonly string[]): UnknownAttribute[] {
  const knownSet = new Set(known);
  const unknown: UnknownAttribute[] = [];
  for (const name of names) {
    if (knownSet.has(name) || GLOBAL_ATTRIBUTE.test(name)) continue;
    const suggestion = closest(name, known);
    const message = `unknown attribute "${name}" ignored${suggestion ? ` (did you mean "${suggestion}"?)` : ''}`;
    unknown.push({ message, attribute: name, ...(suggestion ? { suggestion } : {}) });
  }
  return unknown;
}

/** The known name nearest to `name` (edit distance at most 2; the first of equals), or null. */
function closest(name: string, known: readonly string[]): string | null {
  let best: string | null = null;
  let bestDistance = 3;
  for (const candidate of known) {
    const d = editDistance(name, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

/** Levenshtein distance (insertions, deletions, substitutions), one row at a time. */
function editDistance(a: string, b: string): number {
  const row = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    let previous = row[0];
    row[0] = i;
    for (let j = 1; j <= b.length; j++) {
      const current = row[j];
      row[j] = Math.min(row[j] + 1, row[j - 1] + 1, previous + (a[i - 1] === b[j - 1] ? 0 : 1));
      previous = current;
    }
  }
  return row[b.length];
}
