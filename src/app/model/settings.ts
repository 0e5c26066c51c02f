/**
 * The page's configuration: its defaults (small enough to run in a few seconds on a software
 * GPU), and where it lives between visits: the URL (`?config=<JSON>`, a shareable link that
 * reproduces the result) and localStorage (the last configuration the user ran without a link,
 * used when the URL has none). A link is untrusted input: validated, shown, never stored.
 * Closed surfaces are part of it; a mesh is its sample URL (/meshes/<name>) or, for a user's
 * file, only its name (see meshFiles.ts).
 */
import { validateAnyConfig, type AnyConfig } from '../../core/config';
import { APP_DEFAULTS } from '../../core/config/presets';

/** The app's default sheet (shared with the element): a short tube, 150 cells, surface ratio 1.5. */
export { APP_DEFAULTS } from '../../core/config/presets';

const STORAGE_KEY = 'tissue-sheet:last-config';
const URL_PARAM = 'config';

export function defaultConfig(): AnyConfig {
  return validateAnyConfig(APP_DEFAULTS);
}

/** The config written in a URL, or null when there is none (throws ConfigError when invalid). */
export function configFromUrl(href: string): AnyConfig | null {
  const text = new URL(href).searchParams.get(URL_PARAM);
  if (text === null) return null;
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    throw new Error(`The link's configuration is not valid JSON; nothing was run.`);
  }
  return validateAnyConfig(data);
}

/** A link to this page that reproduces `config`. */
export function urlWithConfig(href: string, config: AnyConfig): string {
  const url = new URL(href);
  url.searchParams.set(URL_PARAM, JSON.stringify(config));
  return url.toString();
}

export function configFromStorage(storage: Storage | undefined = globalThis.localStorage): AnyConfig | null {
  try {
    const text = storage?.getItem(STORAGE_KEY);
    return text ? validateAnyConfig(JSON.parse(text)) : null;
  } catch {
    return null; // an old or damaged session is not worth an error message
  }
}

/**
 * After a run: the address reproduces it, and localStorage keeps it for the next visit without
 * a link, unless it is exactly the configuration of the link the page was opened with (a link's
 * configuration is never stored, and its address is left as it is: the link is its state).
 */
export function saveConfig(config: AnyConfig, fromLink: AnyConfig | null = null): void {
  // The link's own configuration: the address already reproduces it and stays as it was.
  if (fromLink && JSON.stringify(fromLink) === JSON.stringify(config)) return;
  try {
    globalThis.localStorage?.setItem(STORAGE_KEY, JSON.stringify(config));
  } catch {
    // storage full or disabled: the URL still holds the configuration
  }
  const next = urlWithConfig(location.href, config);
  if (next !== location.href) history.replaceState(null, '', next);
}

/** What the address holds: no configuration, a valid one, or one that cannot be used (and why). */
export type LinkState = { kind: 'none' } | { kind: 'ok'; config: AnyConfig } | { kind: 'bad'; message: string };

/** Reads `?config=` of `href` without throwing. */
export function readLink(href: string): LinkState {
  try {
    const config = configFromUrl(href);
    return config ? { kind: 'ok', config } : { kind: 'none' };
  } catch (error) {
    return { kind: 'bad', message: (error as Error).message };
  }
}

/**
 * The configuration the page opens with: the link's when it is valid (a link is its own state),
 * else the last configuration the user ran without a link, else the defaults.
 */
export function initialConfig(link: LinkState): AnyConfig {
  if (link.kind === 'ok') return link.config;
  return configFromStorage() ?? defaultConfig();
}
