// Displacement along the normal by the height map (DESIGN §11), for the -DDISPLACE evaluation
// shaders (surface.tese, tri_surface.tese). Needs common.glsl first.
//   height = scale * map(uv) + bias, the window's own scale and bias or the document's;
//   map: sampled at the mip level the view shows there when band limiting is on (adaptive levels
//       with tess.heightDetail), else its full resolution;
//   uv: the window's parameters mapped into its rectangle of the map (a net's windows tile it), or
//       the planar projection along the up axis, which depends on the position alone and so is the
//       same on both sides of every seam (positions there are bit-identical, DESIGN §2);
//   the shading normal is the displaced surface's: D_u = P_u + h_u n, D_v = P_v + h_v n, with h_u
//   and h_v from the map's gradient (central differences, one texel apart) through the chain rule,
//   like the normal-map approach of the notes (the change of n itself is left out).
layout(set = 0, binding = 3) uniform sampler2D heightMap;

float mapHeight(vec2 uv, float lod) { return textureLod(heightMap, uv, lod).r; }

// Displaces p along n (unit) and turns n into the displaced surface's normal. param: the window's
// (u, v); du, dv: the surface's derivatives along them.
void displaceSurface(inout vec3 p, inout vec3 n, vec3 du, vec3 dv, vec2 param, PatchData pd) {
    vec2 sb = displacementScaleBias(pd);
    float scale = sb.x, bias = sb.y;
    vec2 uv, uvDu, uvDv;  // map coordinates and their derivatives along u and v
    if (frame.displace.z > 0.5) {
        bool zUp = frame.displace.w > 0.5;
        uv = vec2((p.x - frame.planar.x) * frame.planar.z, 1.0 - ((zUp ? p.y : p.z) - frame.planar.y) * frame.planar.w);
        uvDu = vec2(du.x * frame.planar.z, -(zUp ? du.y : du.z) * frame.planar.w);
        uvDv = vec2(dv.x * frame.planar.z, -(zUp ? dv.y : dv.z) * frame.planar.w);
    } else {
        // (1 - t) a + t b: exactly a at t = 0 and b at t = 1, so neighbouring windows meet on one texel line.
        uv = pd.uvRect.xy * (vec2(1.0) - param) + pd.uvRect.zw * param;
        uvDu = vec2(pd.uvRect.z - pd.uvRect.x, 0.0);
        uvDv = vec2(0.0, pd.uvRect.w - pd.uvRect.y);
    }
    // Band-limited (core/gpu/patch_math.h heightMapLod): the mip level the view shows at the
    // undisplaced point, the same on both sides of a seam; the gradient one texel of that level apart.
    float lod = heightMapLod(frame.heightLod.x, pixelsPerUnit(frame.lodViewProj, p, frame.viewport.y), frame.heightLod.y);
    vec2 texel = exp2(floor(lod)) / vec2(textureSize(heightMap, 0));
    float h = scale * mapHeight(uv, lod) + bias;
    vec2 grad = vec2(mapHeight(uv + vec2(texel.x, 0.0), lod) - mapHeight(uv - vec2(texel.x, 0.0), lod),
                     mapHeight(uv + vec2(0.0, texel.y), lod) - mapHeight(uv - vec2(0.0, texel.y), lod)) * scale / (2.0 * texel);
    vec3 Du = du + dot(grad, uvDu) * n, Dv = dv + dot(grad, uvDv) * n;
    vec3 nd = cross(Du, Dv);
    float len2 = dot(nd, nd);
    p += h * n;
    // Where the derivatives vanish (collapsed edges) the undisplaced normal stays.
    if (len2 > 1e-24 && dot(du, du) > 0.0 && dot(dv, dv) > 0.0) {
        nd *= inversesqrt(len2);
        n = dot(nd, n) < 0.0 ? -nd : nd;
    }
}
