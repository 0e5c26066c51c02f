/**
 * Sources a configuration asks to load (`surface.src` of a mesh, `density.src` of a density
 * image; the element's `src` attribute is `surface.src`): a link or an attribute can come from
 * anyone, so only the page's own origin and `data:` URLs load on their own. Anything else, a
 * private address on the visitor's network included, is named to the user ("this link asks to
 * load PATH from HOST") and loads only after a click (`approveSource`). Approvals live in memory
 * for the page's lifetime, never in storage.
 *
 * Every source the page loads goes through `fetchSourceBytes`: a source that needs approval and
 * has none is refused without a request. The app's Content-Security-Policy (index.html) has
 * `connect-src 'self'`, so the page itself cannot reach another origin at all; an approved
 * foreign source is fetched by the source relay (public/source-relay.html, named by the
 * page's `<meta name="tissue-sheet-source-relay">`), a same-origin frame with its own policy,
 * created on the first approved fetch and handed exactly the approved URL
 * (SECURITY.md, "Foreign sources under the CSP"). Without that meta (the element in someone
 * else's page) an approved source is fetched directly, under the host page's own policy.
 */
import { ConfigError, type Config } from '../core/config';
import { MAX_MESH_BYTES, MAX_PNG_BYTES } from '../core/inputLimits';

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
export function pendingSources(config: Config, pageHref: string): ForeignSource[] {
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

/** The page's own sources, or an approved foreign one: at most this many bytes are read (the limit every host shares). */
const MAX_SOURCE_BYTES = Math.max(MAX_MESH_BYTES, MAX_PNG_BYTES);

/**
 * The bytes of `src` (a same-origin URL, a data: or blob: URL, or a foreign URL the user
 * approved). A foreign source without approval is refused with no request made. Errors are
 * one-line ConfigErrors on `field`.
 */
export async function fetchSourceBytes(field: SourceField, src: string): Promise<ArrayBuffer> {
  const foreign = foreignSource(field, src, location.href);
  if (foreign && !approved.has(foreign.href)) {
    throw new ConfigError(
      field,
      `${field}: ${foreign.path} from ${foreign.host} needs your approval before it is loaded; click the button that offers to load it`,
    );
  }
  let data: ArrayBuffer;
  try {
    const relay = foreign ? relayAddress() : null;
    data = relay ? await fetchThroughRelay(relay, foreign!.href) : await fetchDirect(src);
  } catch (error) {
    if (error instanceof ConfigError) throw error;
    throw new ConfigError(field, `${field}: cannot fetch "${src}" (${(error as Error).message}); give a reachable URL`);
  }
  if (data.byteLength > MAX_SOURCE_BYTES) {
    throw new ConfigError(field, `${field}: "${src}" is ${data.byteLength} bytes, more than the ${MAX_SOURCE_BYTES} the page reads; use a smaller file`);
  }
  return data;
}

async function fetchDirect(src: string): Promise<ArrayBuffer> {
  const response = await fetch(src, { credentials: 'same-origin', referrerPolicy: 'no-referrer' });
  if (!response.ok) throw new Error(response.status === 404 ? 'not found (HTTP 404)' : `HTTP ${response.status}`);
  // A development server answers a missing file with its web page (HTTP 200, text/html): that is
  // a file not found, not a mesh or image that failed to parse.
  if (/text\/html/i.test(response.headers.get('content-type') ?? '')) throw new Error('not found: the server answered with a web page, not the file');
  return response.arrayBuffer();
}

/** The relay page named by the document's meta, or null (then sources are fetched directly). */
function relayAddress(): string | null {
  if (typeof document === 'undefined') return null;
  const meta = document.querySelector<HTMLMetaElement>('meta[name="tissue-sheet-source-relay"]');
  return meta?.content ? new URL(meta.content, document.baseURI).href : null;
}

let relayFrame: Promise<HTMLIFrameElement> | null = null;
let relayRequests = 0;

/** Fetches `href` in the relay frame; its bytes come back by postMessage (transferred). */
async function fetchThroughRelay(relay: string, href: string): Promise<ArrayBuffer> {
  relayFrame ??= new Promise<HTMLIFrameElement>((resolve, reject) => {
    const frame = document.createElement('iframe');
    frame.hidden = true;
    frame.title = 'source relay';
    frame.src = relay;
    frame.addEventListener('load', () => resolve(frame), { once: true });
    frame.addEventListener('error', () => reject(new Error('the source relay did not load')), { once: true });
    document.body.append(frame);
  });
  const frame = await relayFrame;
  const origin = new URL(relay).origin;
  const id = ++relayRequests;
  return new Promise<ArrayBuffer>((resolve, reject) => {
    const onMessage = (event: MessageEvent) => {
      if (event.source !== frame.contentWindow || event.origin !== origin) return;
      const reply = event.data as { id?: number; data?: ArrayBuffer; error?: string };
      if (reply?.id !== id) return;
      removeEventListener('message', onMessage);
      if (reply.data instanceof ArrayBuffer) resolve(reply.data);
      else reject(new Error(reply.error ?? 'the source relay gave no data'));
    };
    addEventListener('message', onMessage);
    frame.contentWindow!.postMessage({ id, href }, origin);
  });
}

function safeUrl(text: string): URL | null {
  try {
    return new URL(text);
  } catch {
    return null;
  }
}
