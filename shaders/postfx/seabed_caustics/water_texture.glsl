// The host's water texture (WaterSurface::texture) on its unit: one 2D texture for a single
// cascade (POSTFX_WATER_SINGLE_2D) or a 2D array of one layer per cascade; WATER_COORD(uv, c)
// addresses cascade c's texel at uv either way.
#if POSTFX_WATER_SINGLE_2D
layout(binding = POSTFX_UNIT_WATER) uniform sampler2D waterSurface;
#define WATER_COORD(uv, layer) (uv)
#else
layout(binding = POSTFX_UNIT_WATER) uniform sampler2DArray waterSurface;
#define WATER_COORD(uv, layer) vec3(uv, float(layer))
#endif
