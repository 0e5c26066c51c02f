/**
 * The run configuration: its JSON Schema (the single source of truth for fields, defaults and
 * ranges), the TypeScript types, validation with one-line errors, and the grid it implies;
 * one module each.
 *
 * Why a schema and not hand-written checks: the same document drives validation, default
 * filling (ajv `useDefaults`) and the reference in docs/config.md, so they cannot drift apart.
 * Unions (`surface`, `density`) use ajv's `discriminator` on `kind`, so an error inside a union
 * names the branch the user meant instead of "must match exactly one schema".
 */
export * from './types';
export * from './schema';
export * from './validate';
export * from './feasibility';
