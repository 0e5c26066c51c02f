/**
 * The page's configuration: the example it opens with the first time (every field it leaves
 * out takes the schema's default, as everywhere), and where it lives between visits: the URL (`?config=<JSON>`, a shareable link that
 * reproduces the result) and localStorage (the last configuration the user ran without a link,
 * used when the URL has none). A link is untrusted input: validated, shown, never stored.
 * Closed surfaces are part of it; a mesh is its sample URL (/meshes/<name>) or, for a user's
 * file, only its name (see meshFiles.ts).
 */
import { validateConfigDraft, type ConfigDraft } from '../../core/config';
import { APP_START } from '../../core/config/presets';

const STORAGE_KEY = 'tissue-sheet:last-config';
const URL_PARAM = 'config';

/** The example sheet the page opens with the first time (schema defaults for every other field). */
export function startConfig(): ConfigDraft {
  return validateConfigDraft(APP_START);
}

/**
 * The config written in a URL, or null when there is none (throws ConfigError when invalid). A
 * resolution the link leaves out stays null: the default of the fields it depends on.
 */
export function configFromUrl(href: string): ConfigDraft | null {
  const text = new URL(href).searchParams.get(URL_PARAM);
  if (text === null) return null;
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    throw new Error(`The link's configuration is not valid JSON; nothing was run.`);
  }
  return validateConfigDraft(data);
}

/** A link to this page that reproduces `config`. */
export function urlWithConfig(href: string, config: ConfigDraft): string {
  const url = new URL(href);
  url.searchParams.set(URL_PARAM, JSON.stringify(config));
  return url.toString();
}

function configFromStorage(): ConfigDraft | null {
  const storage: Storage | undefined = globalThis.localStorage;
  try {
    const text = storage?.getItem(STORAGE_KEY);
    return text ? validateConfigDraft(JSON.parse(text)) : null;
  } catch {
    return null; // an old or damaged session is not worth an error message
  }
}

/** The link the page was opened with: its configuration and its address as given. */
export interface OpenedLink {
  readonly config: ConfigDraft;
  readonly href: string;
}

/**
 * After a run: the address describes the result on screen, and localStorage keeps it for the
 * next visit without a link. The configuration of the link the page was opened with is never
 * stored (a link is untrusted input), and its address goes back to the link as it was given
 * (after other runs, e.g. seed 1 -> 2 -> 1, the address says seed 1 again, not 2).
 */
export function saveConfig(config: ConfigDraft, link: OpenedLink | null = null): void {
  if (link && JSON.stringify(link.config) === JSON.stringify(config)) {
    if (link.href !== location.href) history.replaceState(null, '', link.href);
    return;
  }
  try {
    globalThis.localStorage?.setItem(STORAGE_KEY, JSON.stringify(config));
  } catch {
    // storage full or disabled: the URL still holds the configuration
  }
  const next = urlWithConfig(location.href, config);
  if (next !== location.href) history.replaceState(null, '', next);
}

/** What the address holds: no configuration, a valid one, or one that cannot be used (and why). */
export type LinkState = { kind: 'none' } | { kind: 'ok'; config: ConfigDraft } | { kind: 'bad'; message: string };

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
 * else the last configuration the user ran without a link, else the example sheet.
 */
export function initialConfig(link: LinkState): ConfigDraft {
  if (link.kind === 'ok') return link.config;
  return configFromStorage() ?? startConfig();
}
