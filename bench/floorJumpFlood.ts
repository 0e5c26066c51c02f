/**
 * The benchmark's floor: a minimal hand-written WebGL2 jump flood with no three.js, no periodic
 * wrap and no site texture: each texel stores its nearest seed's coordinates (RG32F) and the
 * passes ping-pong between two framebuffers. The engine's jump flood is compared against it at
 * the same size and with the same step schedule.
 */
const vertexSource = `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}`;

const floodSource = `#version 300 es
precision highp float;
uniform highp sampler2D seeds;
uniform int stepSize;
out vec4 outSeed;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(seeds, 0);
  vec2 centre = vec2(p) + 0.5;
  vec2 best = texelFetch(seeds, p, 0).xy;
  float bestDistance = best.x < 0.0 ? 3.4e38 : dot(best - centre, best - centre);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = p + ivec2(dx, dy) * stepSize;
      if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
      vec2 seed = texelFetch(seeds, q, 0).xy;
      if (seed.x < 0.0) continue;
      float d = dot(seed - centre, seed - centre);
      if (d < bestDistance) { best = seed; bestDistance = d; }
    }
  }
  outSeed = vec4(best, 0.0, 1.0);
}`;

export class FloorJumpFlood {
  private readonly program: WebGLProgram;
  private readonly textures: WebGLTexture[] = [];
  private readonly framebuffers: WebGLFramebuffer[] = [];
  private readonly stepLocation: WebGLUniformLocation | null;
  private readonly vao: WebGLVertexArrayObject;
  private readonly pixel = new Float32Array(4);
  private current = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    readonly width: number,
    readonly height: number,
  ) {
    gl.getExtension('EXT_color_buffer_float');
    this.program = link(gl, vertexSource, floodSource);
    this.stepLocation = gl.getUniformLocation(this.program, 'stepSize');
    this.vao = gl.createVertexArray()!;
    for (let i = 0; i < 2; i++) {
      const texture = gl.createTexture()!;
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RG32F, width, height);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      const framebuffer = gl.createFramebuffer()!;
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      this.textures.push(texture);
      this.framebuffers.push(framebuffer);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  /** Uploads seeds (interleaved x, y in texel units) into an otherwise empty (-1) texture. */
  setSeeds(sites: ArrayLike<number>, count: number): void {
    const data = new Float32Array(this.width * this.height * 2).fill(-1);
    for (let i = 0; i < count; i++) {
      const x = Math.min(this.width - 1, Math.floor(sites[2 * i]));
      const y = Math.min(this.height - 1, Math.floor(sites[2 * i + 1]));
      data[2 * (y * this.width + x)] = sites[2 * i];
      data[2 * (y * this.width + x) + 1] = sites[2 * i + 1];
    }
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.textures[0]);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, this.width, this.height, gl.RG, gl.FLOAT, data);
    this.current = 0;
  }

  /** Runs the passes and waits for the GPU. */
  flood(steps: readonly number[]): void {
    const gl = this.gl;
    gl.useProgram(this.program);
    gl.bindVertexArray(this.vao);
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    gl.viewport(0, 0, this.width, this.height);
    gl.activeTexture(gl.TEXTURE0);
    for (const step of steps) {
      gl.bindTexture(gl.TEXTURE_2D, this.textures[this.current]);
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffers[1 - this.current]);
      gl.uniform1i(this.stepLocation, step);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      this.current = 1 - this.current;
    }
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, this.pixel);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.bindVertexArray(null);
  }

  dispose(): void {
    const gl = this.gl;
    for (const texture of this.textures) gl.deleteTexture(texture);
    for (const framebuffer of this.framebuffers) gl.deleteFramebuffer(framebuffer);
    gl.deleteVertexArray(this.vao);
    gl.deleteProgram(this.program);
  }
}

function link(gl: WebGL2RenderingContext, vertex: string, fragment: string): WebGLProgram {
  const program = gl.createProgram()!;
  for (const [type, source] of [
    [gl.VERTEX_SHADER, vertex],
    [gl.FRAGMENT_SHADER, fragment],
  ] as const) {
    const shader = gl.createShader(type)!;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader) ?? 'compile failed');
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program) ?? 'link failed');
  return program;
}
