/**
 * A run summary's values in flattenSummary's key order, without building its keys: a sweep's
 * thread flattens thousands of summaries of a few distinct shapes, and building every key
 * ("exact.layer12.polygons.7", hundreds per run) and an object of them per run was a good part
 * of a thread's time. `shape` names the keys (two values with the same shape flatten to the same
 * key list), so flattenSummary runs once per shape. The values are in the order of
 * `flatKeys(value)`; where that is not flattenSummary's key list (flattened keys that coincide,
 * e.g. "a.b" and a: { b }; an empty top-level key; integer-like top-level keys that an object
 * reorders) the caller uses flattenSummary for that shape.
 */
export function flatValues(value: unknown): { shape: string; values: unknown[] } {
  const shape: string[] = [];
  const values: unknown[] = [];
  walk(value, false, shape, values);
  return { shape: shape.join(''), values };
}

/**
 * As flattenSummary's recursion; `named`: its prefix would not be empty. Keys are written
 * length-first, so a shape reads one way only.
 */
function walk(value: unknown, named: boolean, shape: string[], values: unknown[]): void {
  if (value === null || typeof value !== 'object') {
    if (named) values.push(value);
    return;
  }
  const list = Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView)) ? (value as ArrayLike<unknown>) : null;
  if (list) {
    shape.push(`[${list.length}`);
    if (list.length === 0 && named) values.push('');
    for (let k = 0; k < list.length; k++) walk(list[k], true, shape, values);
    shape.push(']');
    return;
  }
  const record = value as Record<string, unknown>;
  const keys = Object.keys(record);
  shape.push('{');
  if (keys.length === 0 && named) values.push('');
  for (const k of keys) {
    shape.push(`${k.length}:${k}`);
    walk(record[k], named || k !== '', shape, values);
  }
  shape.push('}');
}

/** The keys of flatValues' values, in their order (flattenSummary's keys, where they are one per value). */
export function flatKeys(value: unknown, prefix = '', out: string[] = []): string[] {
  if (value === null || typeof value !== 'object') {
    if (prefix) out.push(prefix);
    return out;
  }
  const list = Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView)) ? (value as ArrayLike<unknown>) : null;
  const record = value as Record<string, unknown>;
  const keys = list ? Array.from({ length: list.length }, (_, k) => String(k)) : Object.keys(record);
  if (keys.length === 0 && prefix) out.push(prefix);
  keys.forEach((k, n) => flatKeys(list ? list[n] : record[k], prefix ? `${prefix}.${k}` : k, out));
  return out;
}
