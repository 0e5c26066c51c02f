/**
 * Parts of the page that keep their own state in the project file beside the simulated sheet
 * (e.g. the measured tissue, measureProject.ts), without project.ts or main.ts knowing them:
 * each registers a section by name; saving writes every section that has something to keep
 * under `sections.NAME`, opening hands each stored section back to its owner. A section the
 * page does not know is refused by name (never silently dropped).
 */
export interface ProjectSection {
  /** Reads what save() needs that only comes asynchronously (file bytes); called before saving. */
  prepare?(): Promise<void>;
  /** What to keep (JSON-ready), or null when there is nothing. */
  save(): unknown;
  /** Restores from what save() gave; throws with a one-line message naming the problem. */
  open(data: unknown, file: string): Promise<void> | void;
}

const sections = new Map<string, ProjectSection>();

export function registerProjectSection(name: string, section: ProjectSection): void {
  sections.set(name, section);
}

/** Lets every section read what it will save (before projectJson, which is synchronous). */
export async function prepareSections(): Promise<void> {
  for (const section of sections.values()) await section.prepare?.();
}

/** The sections with something to keep, or undefined when none has. */
export function savedSections(): Record<string, unknown> | undefined {
  const out: Record<string, unknown> = {};
  for (const [name, section] of sections) {
    const data = section.save();
    if (data !== null && data !== undefined) out[name] = data;
  }
  return Object.keys(out).length > 0 ? out : undefined;
}

/** Hands each stored section to its owner (in the file's order). */
export async function openSections(stored: unknown, file: string): Promise<void> {
  if (stored === undefined) return;
  if (typeof stored !== 'object' || stored === null || Array.isArray(stored)) throw new Error(`${file}: sections: expected an object.`);
  for (const name of Object.keys(stored)) {
    const section = sections.get(name);
    if (!section) throw new Error(`${file}: sections.${name}: this page does not know that part of a project.`);
    await section.open((stored as Record<string, unknown>)[name], file);
  }
}
