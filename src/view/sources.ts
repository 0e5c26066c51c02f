/**
 * Sources a configuration asks to load (`surface.src` of a mesh, `density.src` of a density
 * image; the element's `src` attribute is `surface.src`): a link or an attribute can come from
 * anyone, so only the page's own origin and `data:` URLs load on their own. Anything else, a
 * private address on the visitor's network included, is named to the user ("this link asks to
 * load PATH from HOST") and loads only after a click (`approveSource`). Approvals live in memory
 * for the page's lifetime, never in storage. Pure apart from that set; no DOM.
 */
import type { AnyConfig } from '../core/config';

export type SourceField = 'surface.src' | 'density.src';

export interface ForeignSource {
  field: SourceField;
  /** The absolute URL that would be requested. */
  href: string;
  /** "host:port" as written in the URL (or the scheme, for one without a host). */
  host: string;
  /** Path and query. */
  path: string;
}

/**
 * Null when `src` may load without asking: an upload's name (no "/"), a `data:` URL, or a URL
 * of the page's own origin (relative paths included); else what it would fetch and from where.
 */
export function foreignSource(field: SourceField, src: string, pageHref: string): ForeignSource | null {
  const text = src.trim();
  if (text === '' || text.startsWith('data:')) return null;
  if (field === 'surface.src' && !text.includes('/') && !/^[a-z][a-z0-9+.-]*:/i.test(text)) return null; // an upload's name
  let url: URL;
  let page: URL;
  try {
    page = new URL(pageHref);
    url = new URL(text, page);
  } catch {
    // Not a URL at all: nothing can be fetched; the run's own loader reports it.
    return null;
  }
  if (url.protocol === 'blob:') {
    // blob: URLs carry the origin that made them.
    const inner = safeUrl(url.pathname);
    if (inner && inner.origin === page.origin) return null;
  } else if (url.origin === page.origin && (url.protocol === 'http:' || url.protocol === 'https:')) {
    return null;
  }
  return { field, href: url.href, host: url.host || url.protocol.replace(/:$/, ''), path: `${url.pathname}${url.search}` };
}

/** Every source of `config` that needs the user's approval (not yet approved). */
export function pendingSources(config: AnyConfig, pageHref: string): ForeignSource[] {
  const found: ForeignSource[] = [];
  if (config.surface.kind === 'mesh') {
    const s = foreignSource('surface.src', config.surface.src, pageHref);
    if (s) found.push(s);
  }
  if (config.density.kind === 'image') {
    const s = foreignSource('density.src', config.density.src, pageHref);
    if (s) found.push(s);
  }
  return found.filter((s) => !approved.has(s.href));
}

/** The sentence shown before loading: "this link asks to load PATH from HOST". */
export function sourceQuestion(source: ForeignSource, who = 'This link'): string {
  const what = source.field === 'surface.src' ? 'a mesh' : 'a density image';
  return `${who} asks to load ${what}, ${source.path}, from ${source.host}. Nothing has been requested from ${source.host} yet.`;
}

const approved = new Set<string>();

/** The user clicked to load `source`: it may be requested from now on (this page only). */
export function approveSource(source: ForeignSource): void {
  approved.add(source.href);
}

function safeUrl(text: string): URL | null {
  try {
    return new URL(text);
  } catch {
    return null;
  }
}
