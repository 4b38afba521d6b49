// Lookup of "rmsm" (resolution-matched shadow maps), over ShadowMap.glsl's filter with
// SHADOW_MAP_PAGES: the page table names, per cell of the finest level, the finest page built
// over it; the filter then reads that page's slot in the atlas (u_shadowMap, one layer), whose
// apron holds the neighbours' texels of the same level, so taps never cross a page border.
// deepshadow::LocatePage and ResolutionMatchedShadow::MapVisibility are the CPU twins.
//@Dec
uniform usampler2DArray u_pageTable; // per face, per finest cell: slot | level << 24
uniform int u_pageSize;
uniform int u_apron;
uniform int u_slotsPerSide;
uniform int u_finestLevel;
uniform float u_atlasSize;

// Texel `texel` of slot `slot` (clamped to the slot, as FilterShadowMap clamps to its map).
float shadowMapDepth(int slot, ivec2 texel)
{
  int slotSize = u_pageSize + 2 * u_apron;
  ivec2 origin = ivec2(slot % u_slotsPerSide, slot / u_slotsPerSide) * slotSize;
  ivec2 at = origin + clamp(texel, ivec2(0), ivec2(slotSize - 1));
  return textureLod(u_shadowMap, vec3((vec2(at) + 0.5) / u_atlasSize, 0.0), 0.0).r;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  vec2 position = clamp(xy, vec2(-64.0), vec2(u_shadowSize + 64.0));
  ivec2 cell = clamp(ivec2(floor((position + 0.5) / float(u_pageSize))), ivec2(0), ivec2((1 << u_finestLevel) - 1));
  uint entry = texelFetch(u_pageTable, ivec3(cell, layer), 0).r;
  int slot = int(entry & 0xffffffu);
  int coarser = u_finestLevel - int(entry >> 24);
  float scale = exp2(float(coarser));
  // The level's texel position, relative to the slot's first texel (the apron's).
  vec2 local = (position + 0.5) / scale - 0.5 - vec2((cell >> coarser) * u_pageSize) + float(u_apron);
  return vec3(filteredShadow(slot, local, depth - u_shadowBias, slope * scale));
}
