/**
 * Records of many keys that live long (a sweep's rows, its aggregate's statistics): `recordOf(keys,
 * values)` is `{ [keys[k]]: values[k] }`, a repeated key keeping its last value, as assignments in
 * order do. Built key by key, a record of some 360 keys is a hash table several times the size of
 * one made by a constructor that assigns every key by name, which V8 gives one hidden class with
 * fast properties; the published grid's rows, kept to the end of the sweep, were a good part of
 * what the main thread's garbage collector copied and traced. So the code is generated, once per
 * key list (the same array: callers reuse theirs): a constructor for a template record, and a
 * function that copies the template and stores the values by name (makerFor), the keys entering
 * that code only as JSON string literals, which no key can leave. Where code cannot be generated
 * (a page whose Content-Security-Policy forbids it), or for a list of many thousand keys, the
 * record is built key by key: the same record either way (own enumerable keys in the same order,
 * plain prototype).
 */

/** Largest key list given generated code (its code grows with the list). */
const GENERATED_KEYS = 4096;

type Maker = (values: readonly unknown[]) => Record<string, unknown>;
const makers = new WeakMap<readonly string[], Maker | null>();

export function recordOf<T>(keys: readonly string[], values: readonly T[]): Record<string, T> {
  const make = makerFor(keys);
  if (make) return make(values) as Record<string, T>;
  const record: Record<string, T> = {};
  for (let k = 0; k < keys.length; k++) record[keys[k]] = values[k];
  return record;
}

function makerFor(keys: readonly string[]): Maker | null {
  let make = makers.get(keys);
  if (make === undefined) {
    make = null;
    if (keys.length <= GENERATED_KEYS) {
      try {
        // A template record from a constructor that assigns every key (one hidden class, fast
        // properties), then each record a copy of it with its values stored by name: copying
        // the template allocates the record at its full size at once, where the constructor
        // grew the properties past the in-object ones a few at a time (twice the garbage and
        // several times the time for the published grid's rows of some 360 keys).
        const assign = keys.map((key) => `this[${JSON.stringify(key)}] = undefined;`).join('\n');
        const Template = new Function(assign) as unknown as new () => Record<string, unknown>;
        // Plain records (Object.prototype), like those built key by key.
        Template.prototype = Object.prototype;
        const template = new Template();
        const store = keys.map((key, k) => `r[${JSON.stringify(key)}] = v[${k}];`).join('\n');
        const fill = new Function('t', 'v', `const r = { ...t };\n${store}\nreturn r;`) as (
          template: object,
          values: readonly unknown[],
        ) => Record<string, unknown>;
        make = (values) => fill(template, values);
      } catch {
        make = null;
      }
    }
    makers.set(keys, make);
  }
  return make;
}

/**
 * One array per distinct key list (by content; the last 64 lists kept), so that records made
 * from lists built anew each time (an aggregate's columns, a point's keys) share a constructor.
 */
const interned = new Map<string, readonly string[]>();
export function internKeys(keys: readonly string[]): readonly string[] {
  const id = JSON.stringify(keys);
  let kept = interned.get(id);
  if (!kept) {
    if (interned.size >= 64) interned.clear();
    interned.set(id, (kept = [...keys]));
  }
  return kept;
}
