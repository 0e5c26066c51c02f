/**
 * A configuration problem. `field` is a dotted path (`surface.radius`, `density.center[1]`).
 * In a module of its own: validation, feasibility and the method rules all throw it, and
 * validation calls feasibility (the default resolution), so none of them may own it.
 */
export class ConfigError extends Error {
  readonly field: string;
  constructor(field: string, message: string) {
    super(message);
    this.name = 'ConfigError';
    this.field = field;
  }
}
