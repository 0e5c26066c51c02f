import * as THREE from 'three';

/**
 * A shader program drawn with no vertex attributes: a fullscreen triangle (3 vertices) or a
 * cloud of points whose vertex shader places them from gl_VertexID. Built once; each draw
 * only changes uniforms and the draw count, so nothing is compiled or allocated per frame.
 */
export class ShaderPass {
  readonly material: THREE.RawShaderMaterial;
  private readonly geometry = new THREE.BufferGeometry();
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.Camera();

  constructor(
    kind: 'triangles' | 'points',
    vertexShader: string,
    fragmentShader: string,
    uniforms: Record<string, THREE.IUniform>,
    additiveBlend = false,
    defines: Record<string, number> = {},
  ) {
    this.material = new THREE.RawShaderMaterial({
      glslVersion: THREE.GLSL3,
      defines,
      vertexShader,
      fragmentShader,
      uniforms,
      depthTest: false,
      depthWrite: false,
    });
    // Additive blending (one + one, colour and alpha) for the centroid scatter; none elsewhere.
    const add = { blendEquation: THREE.AddEquation, blendSrc: THREE.OneFactor, blendDst: THREE.OneFactor };
    const alpha = { blendEquationAlpha: THREE.AddEquation, blendSrcAlpha: THREE.OneFactor, blendDstAlpha: THREE.OneFactor };
    Object.assign(this.material, additiveBlend ? { blending: THREE.CustomBlending, ...add, ...alpha } : { blending: THREE.NoBlending });
    const object = kind === 'points' ? new THREE.Points(this.geometry, this.material) : new THREE.Mesh(this.geometry, this.material);
    object.frustumCulled = false;
    this.geometry.setDrawRange(0, 3);
    this.scene.add(object);
  }

  get uniforms(): Record<string, THREE.IUniform> {
    return this.material.uniforms;
  }

  /** Draws `count` vertices into `target` (its whole area is the viewport). */
  draw(renderer: THREE.WebGLRenderer, target: THREE.WebGLRenderTarget, count = 3): void {
    this.geometry.drawRange.count = count;
    renderer.setRenderTarget(target);
    renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    this.geometry.dispose();
    this.material.dispose();
  }
}
