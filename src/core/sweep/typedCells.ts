/**
 * The numbers of the rows runCells makes (each cell as the aggregate reads it), kept beside each
 * row object, so the aggregate of a sweep's rows reads its numbers without parsing them back from
 * their text (a sweep of 2,400 runs x 400 columns spent a good part of its last half second
 * there, after every run). A row's text of a number is String(number), whose Number() is that
 * number again (-0 reads back as 0, which no mean, SD or count tells apart), so the aggregate is
 * the same either way; rows read from a file have no typed cells and are parsed as before.
 */
export interface Typed {
  readonly header: readonly string[];
  /**
   * Each cell as the aggregate reads it (cellNumber of its text): a number's value, NaN for an
   * empty cell, text parsed as the row's text is. Made as the row is (its cells are in cache
   * then): read after the last run from boxed cells scattered over the heap, the aggregate of
   * 2,400 rows x 340 columns took about 0.2 s, in one contiguous array per row a fraction. The
   * cells themselves are not kept: 2,400 rows of 360 boxed values held to the end of a sweep
   * were a good part of what the main thread's garbage collector traced again and again.
   */
  readonly numbers: Float64Array;
}

const typed = new WeakMap<object, Typed>();

/** Records the numbers of `cells` (in `header` order) as the typed cells of `row` (whose text `row` already holds). */
export function keepTypedCells(row: Readonly<Record<string, string>>, header: readonly string[], cells: readonly unknown[]): void {
  const numbers = new Float64Array(header.length);
  for (let k = 0; k < header.length; k++) {
    const value = cells[k];
    numbers[k] =
      typeof value === 'number' ? value : value === undefined || value === null ? NaN : cellNumber(typeof value === 'string' ? value : row[header[k]]);
  }
  typed.set(row, { header, numbers });
}

/** The typed cells of `row` (runCells' rows), with the header they follow; undefined for other rows. */
export function typedCellsOf(row: object): Typed | undefined {
  return typed.get(row);
}

/**
 * A cell's text as a number: Number() of text that is not a number (text, "NaN") is NaN, left
 * out as missing; a blank cell would read as 0, so it is NaN too.
 */
export function cellNumber(cell: string | undefined): number {
  return cell === undefined || cell.trim() === '' ? NaN : Number(cell);
}

/** Each header's column positions, once per header (all rows of a sweep share one). */
const positions = new WeakMap<readonly string[], Map<string, number>>();

/** The position of `column` in `header` (-1 when absent). */
export function columnPosition(header: readonly string[], column: string): number {
  let at = positions.get(header);
  if (!at) positions.set(header, (at = new Map(header.map((h, k) => [h, k]))));
  return at.get(column) ?? -1;
}
