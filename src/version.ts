import packageJson from '../package.json';

/** The software version written into every result, from package.json. */
export const version: string = packageJson.version;
