/**
 * The page's configuration: its defaults (small enough to run in a few seconds on a software
 * GPU), and where it lives between visits: the URL (`?config=<JSON>`, a shareable link that
 * reproduces the result) and localStorage (the last session, used when the URL has none).
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
    throw new Error(`The link's configuration is not valid JSON; it was ignored and the defaults are shown.`);
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

export function saveConfig(config: AnyConfig): void {
  try {
    globalThis.localStorage?.setItem(STORAGE_KEY, JSON.stringify(config));
  } catch {
    // storage full or disabled: the URL still holds the configuration
  }
  const next = urlWithConfig(location.href, config);
  if (next !== location.href) history.replaceState(null, '', next);
}

/** URL first (a shared link), then the last session, then the defaults. */
export function initialConfig(onWarning: (message: string) => void): AnyConfig {
  try {
    const fromUrl = configFromUrl(location.href);
    if (fromUrl) return fromUrl;
  } catch (error) {
    onWarning(`The link's configuration was not used: ${(error as Error).message}`);
  }
  return configFromStorage() ?? defaultConfig();
}
