/**
 * Centroid pass, portable path (no float blending needed): each site's pixel in the sums
 * target walks a window of texels around its site and adds up the same
 * (w * dx, w * dy, w, w * |d|²) as the scatter pass, for texels labelled with its id. Planar
 * grids only (compiled after surface.glsl and gridMetric.glsl).
 *
 * Site i's window is (2R_i+1)² texels (R_i from the radii texture). One draw covers one tile
 * of the largest window (at most tileSize² texels per pixel, because software renderers
 * silently stop long loops); each pixel walks the part of its own window inside that tile and
 * adds it to the sums of the previous draw (ping-pong). Voronoi cells are convex and hold their
 * site, so a cell that comes nowhere near the window's outer ring lies inside it with all its
 * texels. A thin sliver can cross the ring between texel centres (owning texels beyond, none on
 * it), so a ring texel q of cell j counts as reached when d(q, site) <= d(q, j) + 2h (h: half a
 * texel's diagonal; any point p of q's square in this cell gives d(q, site) <= d(p, j) + h).
 * Then the pixel reports weight -1 (kept through later tiles) and the engine retries with a
 * larger window: a window that is too small is never a silent wrong centroid.
 */
export default /* glsl */ `
uniform highp sampler2D labels;
uniform highp sampler2D previousSums;
uniform bool firstTile;
uniform int siteCount;
uniform highp sampler2D radii;
uniform int maxRadius;
uniform ivec2 tileStart;
uniform int tileSize;
out vec4 sums;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int site = pixel.y * siteWidth + pixel.x;
  vec4 previous = texelFetch(previousSums, pixel, 0);
  float radiusValue = texelFetch(radii, pixel, 0).r;
  if (radiusValue < 0.0) { sums = previous; return; } // finished in an earlier attempt
  vec4 total = firstTile ? vec4(0.0) : previous;
  if (site >= siteCount || total.z < 0.0) { sums = total; return; }
  vec4 siteValue = siteAt(site);
  vec2 position = siteValue.xy;
  int radius = int(radiusValue);
  ivec2 origin = ivec2(floor(position));
  // On a periodic axis the window never covers more than the axis once (no texel twice);
  // an axis covered whole has no ring to touch.
  ivec2 low = ivec2(-radius);
  ivec2 high = ivec2(radius);
  bvec2 whole = bvec2(false);
  for (int axis = 0; axis < 2; ++axis) {
    if (periodic[axis] && 2 * radius + 1 >= atlasSize[axis]) {
      low[axis] = -(atlasSize[axis] / 2);
      high[axis] = low[axis] + atlasSize[axis] - 1;
      whole[axis] = true;
    }
  }
  // This draw's tile of the largest window, clipped to this site's own window.
  ivec2 tileLow = ivec2(-maxRadius) + tileStart;
  for (int axis = 0; axis < 2; ++axis) {
    if (periodic[axis] && 2 * maxRadius + 1 >= atlasSize[axis]) tileLow[axis] = -(atlasSize[axis] / 2) + tileStart[axis];
  }
  ivec2 from = max(low, tileLow);
  ivec2 to = min(high, tileLow + tileSize - 1);
  float slack = sqrt(1.0 + aspect * aspect); // 2h in flood units (y scaled by the aspect)
  bool touchesRing = false;
  for (int dy = from.y; dy <= to.y; ++dy) {
    for (int dx = from.x; dx <= to.x; ++dx) {
      ivec2 q = origin + ivec2(dx, dy);
      if (!wrapTexel(q)) continue;
      vec4 label = texelFetch(labels, q, 0);
      bool ring = (!whole.x && abs(dx) == radius) || (!whole.y && abs(dy) == radius);
      if (label.w != float(site)) {
        if (ring && label.w >= 0.0) { // another cell's ring texel: reached by this cell?
          float other = sqrt(floodDistance(label.xyz, texelPoint(q))) + slack;
          if (floodDistance(siteValue.xyz, texelPoint(q)) <= other * other) touchesRing = true;
        }
        continue;
      }
      if (ring) touchesRing = true;
      vec3 d = metricOffset(siteValue.xyz, texelPoint(q));
      float w = texelWeight(q);
      total += vec4(w * d.xy, w, w * physicalSquared(d));
    }
  }
  sums = touchesRing ? vec4(0.0, 0.0, -1.0, 0.0) : total;
}
`;
