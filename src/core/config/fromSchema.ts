/**
 * TypeScript types computed from a JSON Schema literal (`as const`), for the subset of draft-07
 * that configSchema uses: objects with `properties`/`required`/`default`, `oneOf` unions of
 * objects, `const`, `enum`, `type` (one name or a list such as ["number", "null"]) and arrays
 * (a fixed-length tuple when `minItems` equals `maxItems`).
 *
 * Why our own instead of a library (json-schema-to-ts, TypeBox): the subset is small, the
 * types must come out plain and mutable (validated configs are edited as data), and a
 * type-level interpreter of the whole standard slows every typecheck; this one costs nothing
 * measurable. A schema keyword outside the subset falls through to `unknown`, which the
 * compiler then refuses wherever a typed value is expected, so a new keyword cannot silently
 * lose its type.
 *
 * Two readings of the same schema:
 * - 'output': what validation returns. A property with a `default` is always present (ajv
 *   `useDefaults` fills it), as is a `required` one; any other is optional.
 * - 'input': what a user may write. Only `required` properties must be given.
 */

type SchemaReading = 'output' | 'input';

/** The TypeScript type of the data a schema node accepts, in the given reading. */
export type FromSchema<S, R extends SchemaReading = 'output'> = S extends { readonly oneOf: readonly (infer B)[] }
  ? B extends unknown
    ? FromSchema<B, R>
    : never
  : S extends { readonly const: infer C }
    ? C
    : S extends { readonly enum: readonly (infer E)[] }
      ? E
      : S extends { readonly type: readonly (infer T)[] }
        ? T extends unknown
          ? FromSchema<Omit<S, 'type'> & { readonly type: T }, R>
          : never
        : S extends { readonly type: 'object' }
          ? ObjectFromSchema<S, R>
          : S extends { readonly type: 'array'; readonly items: infer I }
            ? ArrayFromSchema<S, FromSchema<I, R>>
            : S extends { readonly type: 'number' | 'integer' }
              ? number
              : S extends { readonly type: 'string' }
                ? string
                : S extends { readonly type: 'boolean' }
                  ? boolean
                  : S extends { readonly type: 'null' }
                    ? null
                    : unknown;

type PropertiesOf<S> = S extends { readonly properties: infer P } ? P : Record<never, never>;
type RequiredOf<S> = S extends { readonly required: readonly (infer K)[] } ? K : never;

/** Keys that are always present in the reading R. */
type PresentKeys<S, R extends SchemaReading> = {
  [K in keyof PropertiesOf<S>]: K extends RequiredOf<S>
    ? K
    : R extends 'output'
      ? PropertiesOf<S>[K] extends { readonly default: unknown }
        ? K
        : never
      : never;
}[keyof PropertiesOf<S>];

/** Flattens an intersection into one object type (readable in hovers and error messages). */
type Simplify<T> = { [K in keyof T]: T[K] } & {};

type ObjectFromSchema<S, R extends SchemaReading> = Simplify<
  { -readonly [K in keyof PropertiesOf<S> as K extends PresentKeys<S, R> ? K : never]: FromSchema<PropertiesOf<S>[K], R> } & {
    -readonly [K in keyof PropertiesOf<S> as K extends PresentKeys<S, R> ? never : K]?: FromSchema<PropertiesOf<S>[K], R>;
  }
>;

type Tuple<T, N extends number, Acc extends T[] = []> = Acc['length'] extends N ? Acc : Tuple<T, N, [...Acc, T]>;

type ArrayFromSchema<S, Item> = S extends { readonly minItems: infer N extends number; readonly maxItems: infer M extends number }
  ? [N] extends [M]
    ? number extends N
      ? Item[]
      : Tuple<Item, N>
    : Item[]
  : Item[];
