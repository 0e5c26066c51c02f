/**
 * Closed surfaces in the 3D view, per fragment: the fragment's cell is the candidate site
 * nearest to its point in 3D (the restricted Voronoi cell; closedCandidates.ts), so borders are
 * the true bisectors at any zoom. The border line is drawn where the point is within about a
 * pixel of the bisector plane of its two nearest candidates (distance (d2² - d1²) / 2|s2 - s1|,
 * measured in pixels from the point's screen derivatives, so it stays about one pixel wide at
 * any zoom), scutoids are striped in object
 * space with antialiased stripes (no moiré), the picked cell is white, and a fixed light leaves
 * the lit side in the legend's exact colours (closedMaterial.ts).
 */
export default /* glsl */ `
precision highp float;
precision highp int;
#include <clipping_planes_pars_fragment>
uniform highp sampler2D sites;
uniform highp sampler2D cellColors;
uniform int textureWidth;
uniform int selected;
uniform bool highlight;
uniform float stripePeriod;
uniform vec3 lightDirection;
uniform float litFrom;
uniform float shadeMin;
uniform vec3 selectedColor;
uniform vec3 noCellColor;
flat varying vec4 vCandidates;
varying vec3 vPoint;
varying vec3 vNormal;

ivec2 cellTexel(int id) {
  return ivec2(id % textureWidth, id / textureWidth);
}

void main() {
  #include <clipping_planes_fragment>
  int best = -1;
  int second = -1;
  float d1 = 1e38;
  float d2 = 1e38;
  vec3 s1 = vec3(0.0);
  vec3 s2 = vec3(0.0);
  for (int k = 0; k < 4; k++) {
    int id = int(vCandidates[k] + 0.5);
    if (vCandidates[k] < 0.0) continue;
    vec3 s = texelFetch(sites, cellTexel(id), 0).xyz;
    vec3 delta = vPoint - s;
    float d = dot(delta, delta);
    if (d < d1) {
      second = best; d2 = d1; s2 = s1;
      best = id; d1 = d; s1 = s;
    } else if (d < d2) {
      second = id; d2 = d; s2 = s;
    }
  }
  vec3 color = noCellColor;
  if (best >= 0) {
    vec4 cell = texelFetch(cellColors, cellTexel(best), 0);
    color = cell.rgb;
    if (best == selected) {
      color = selectedColor;
    } else if (highlight && cell.a > 0.5) {
      // Stripes across x + y + z, antialiased over one pixel's change of phase.
      float phase = (vPoint.x + vPoint.y + vPoint.z) / stripePeriod;
      float f = fract(phase);
      float w = max(fwidth(phase), 1e-4);
      float dark = smoothstep(0.0, w, f) - smoothstep(0.4, 0.4 + w, f);
      color = mix(color, vec3(0.0070), dark);
    }
  }
  if (second >= 0) {
    float gap = length(s2 - s1);
    float toBorder = (d2 - d1) / max(2.0 * gap, 1e-12);
    // One pixel's footprint on the surface (µm), from the point's screen derivatives: smooth
    // everywhere, unlike derivatives of toBorder, which fold at the border itself.
    float w = max(max(length(dFdx(vPoint)), length(dFdy(vPoint))), 1e-12);
    // About one pixel of border each side: full within 0.5 px of the bisector, fading over the next pixel.
    float line = 1.0 - smoothstep(0.5 * w, 1.5 * w, toBorder);
    color = mix(color, color * 0.05, line);
  }
  vec3 n = normalize(vNormal);
  float facing = dot(n, lightDirection);
  float light = facing >= litFrom ? 1.0 : shadeMin + (1.0 - shadeMin) * (facing + 1.0) / (litFrom + 1.0);
  gl_FragColor = vec4(color * light, 1.0);
  #include <colorspace_fragment>
}
`;
