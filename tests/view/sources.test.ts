import { describe, expect, it } from 'vitest';
import { validateConfig, ConfigError } from '../../src/core/config';
import { checkPageBudget, PAGE_MAX_WORK } from '../../src/view/pageBudget';
import { approveSource, foreignSource, pendingSources, sourceQuestion } from '../../src/view/sources';

const page = 'http://127.0.0.1:5174/?config=%7B%7D';

describe('foreignSource', () => {
  it('lets the page origin, data: URLs and upload names load', () => {
    for (const src of ['/meshes/organoid.ply', 'meshes/x.ply', 'http://127.0.0.1:5174/meshes/a.ply', 'data:text/plain,ply', 'my file.ply', '']) {
      expect(foreignSource('surface.src', src, page), src).toBeNull();
    }
    expect(foreignSource('density.src', 'data:image/png;base64,AAAA', page)).toBeNull();
  });

  it('names host and path of anything else, private addresses and protocol-relative URLs included', () => {
    const cases: [string, string, string][] = [
      ['http://192.168.1.10/admin?x=1', '192.168.1.10', '/admin?x=1'],
      ['http://127.0.0.1:8080/x.ply', '127.0.0.1:8080', '/x.ply'],
      ['//evil.example/m.ply', 'evil.example', '/m.ply'],
      ['https://127.0.0.1:5174/a.ply', '127.0.0.1:5174', '/a.ply'], // another scheme is another origin
      ['ftp://files.example/m.ply', 'files.example', '/m.ply'],
    ];
    for (const [src, host, path] of cases) {
      const s = foreignSource('surface.src', src, page);
      expect(s, src).not.toBeNull();
      expect(s!.host).toBe(host);
      expect(s!.path).toBe(path);
      expect(sourceQuestion(s!)).toContain(`${path}, from ${host}`);
    }
  });

  it('a source is pending until approved', () => {
    const config = validateConfig({ surface: { kind: 'mesh', src: 'http://10.0.0.2/m.ply' }, resolution: 32, cells: 20 });
    const [pending] = pendingSources(config, page);
    expect(pending.href).toBe('http://10.0.0.2/m.ply');
    approveSource(pending);
    expect(pendingSources(config, page)).toEqual([]);
  });
});

describe('checkPageBudget', () => {
  it('refuses before running, naming the estimate and the limit', () => {
    const big = validateConfig({ surface: { kind: 'plane', width: 1000, height: 1000 }, resolution: 8192, cells: 200, lloyd: { maxIterations: 1000 } });
    let error: unknown;
    try {
      checkPageBudget(big, 16384);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(ConfigError);
    expect((error as Error).message).toMatch(/^resolution: this run is .* texel-floods/);
    expect((error as Error).message).toContain('above the limit');
    const small = validateConfig({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 128, cells: 20 });
    expect(checkPageBudget(small, 8192).work).toBeLessThan(PAGE_MAX_WORK);
  });
});
