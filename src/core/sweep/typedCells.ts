/**
 * The typed cells of the rows runCells makes (numbers still numbers), kept beside each row
 * object, so the aggregate of a sweep's rows reads its numbers without parsing them back from
 * their text (a sweep of 2,400 runs x 400 columns spent a good part of its last half second
 * there, after every run). A row's text of a number is String(number), whose Number() is that
 * number again (-0 reads back as 0, which no mean, SD or count tells apart), so the aggregate is
 * the same either way; rows read from a file have no typed cells and are parsed as before.
 */
export interface Typed {
  readonly header: readonly string[];
  readonly cells: readonly unknown[];
}

const typed = new WeakMap<object, Typed>();

/** Records `cells`, in `header` order, as the typed cells of `row`. */
export function keepTypedCells(row: object, header: readonly string[], cells: readonly unknown[]): void {
  typed.set(row, { header, cells });
}

/** The typed cells of `row` (runCells' rows), with the header they follow; undefined for other rows. */
export function typedCellsOf(row: object): Typed | undefined {
  return typed.get(row);
}

/** Each header's column positions, once per header (all rows of a sweep share one). */
const positions = new WeakMap<readonly string[], Map<string, number>>();

/** The position of `column` in `header` (-1 when absent). */
export function columnPosition(header: readonly string[], column: string): number {
  let at = positions.get(header);
  if (!at) positions.set(header, (at = new Map(header.map((h, k) => [h, k]))));
  return at.get(column) ?? -1;
}
