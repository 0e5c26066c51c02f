import type * as THREE from 'three';
import type { ShaderPass } from './shaderPass';

/**
 * Runs the jump-flood passes of a schedule, ping-ponging between two label targets (each pass
 * reads one and writes the other). Returns the index of the target that holds the result.
 */
export function floodPingPong(
  renderer: THREE.WebGLRenderer,
  pass: ShaderPass,
  targets: readonly [THREE.WebGLRenderTarget, THREE.WebGLRenderTarget],
  current: number,
  steps: readonly number[],
): number {
  for (const step of steps) {
    pass.uniforms.labels.value = targets[current].texture;
    pass.uniforms.stepSize.value = step;
    current = 1 - current;
    pass.draw(renderer, targets[current]);
  }
  return current;
}
