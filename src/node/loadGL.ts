import { createRequire } from 'node:module';
import { GpuCapabilityError } from '../gpu/context';

/** headless-gl's factory, as its typings declare it (`export = createContext`). */
export type CreateHeadlessGL = typeof import('gl');

/** The `gl` version this package is tested with (WebGL2 needs 9.x; `gl@8` is WebGL1 only). */
const HEADLESS_GL_VERSION = '9.0.0-rc.10';

/**
 * Loads headless-gl (`gl`), an optional dependency: a browser-only consumer can leave it out
 * (`--omit=optional`) or deny its install script (`"allowScripts": {"gl": false}`), and then
 * it is installed without its native module. Both cases become one GpuCapabilityError (the
 * CLI's exit code 3) saying what to run, instead of a stack trace from `bindings`.
 */
export function loadHeadlessGL(): CreateHeadlessGL {
  const require = createRequire(import.meta.url);
  try {
    require.resolve('gl');
  } catch {
    throw new GpuCapabilityError(
      `headless-gl (the optional dependency gl) is not installed; the Node CLI needs it: ` +
        `npm install gl@${HEADLESS_GL_VERSION} (it builds a native module: python3, make and g++).`,
    );
  }
  try {
    return require('gl') as CreateHeadlessGL;
  } catch (error) {
    const detail = error instanceof Error ? error.message.split('\n')[0].replace(/\s*Tried:$/, '') : String(error);
    throw new GpuCapabilityError(
      `headless-gl (gl) is installed but its native module is not built (${detail}); allow its ` +
        'install script and build it: npm install-scripts approve gl && npm rebuild gl ' +
        '(remove a "gl": false entry from allowScripts first; the build needs python3, make and g++).',
    );
  }
}
