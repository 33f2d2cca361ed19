// GLSL of the volumetric obscurance pass (obscurance_pass.h). The stages read the scene's depth
// and view-space normals with nearest fetches, so no sample blends depths across an edge.
// The estimate and the blur are each a function pass_result(pixel) -> RGBA16F texel, run by
// kComputeMain (an 8 x 8 compute group per tile, GL 4.3: on every shader core, where some GPUs
// run fragment shaders on a few) or by kFragmentMain over a full-screen triangle (GL 3.3);
// the other stages draw one full-screen triangle (kFullscreenVertex).
//
// kEstimate, compiled with "#define VO_LINES n", "VO_POINTS n", "VO_AREA" or
// "VO_REFERENCE k": the fraction
// of the sphere of radius R around each pixel's view-space point that is open (not inside the
// scene), 1 = unoccluded. Lines (the paper's 4.1): each sample (x, y, w) on the unit disk is a
// line through the sphere along the view direction, half-length z_s = R sqrt(1 - x^2 - y^2);
// the part in front of the depth buffer is open, max(min(z_s, d_r) + z_s, 0) with d_r the
// scene's distance minus the pixel's. Points (Crytek style): a sample (x, y, z, w) in the unit
// ball is open unless it lies behind the depth buffer. With the normal clamp (4.4) only the
// part of the sphere above the pixel's tangent plane counts, so a flat surface is fully open;
// without it, the fraction is doubled (a flat surface has half its sphere behind it). With a
// thickness T (4.3) the scene is a shell T deep: what lies behind it is open again, so
// foreground edges do not darken the background behind them. Two radii combine by product or
// minimum. Each pixel rotates (and every other pixel reflects) its sample set by a 4x4 pattern,
// which the blur then averages. Area (4.2): one sample, the mean and variance of the depths
// under the sphere's disk from a mip chain of depth moments (kMomentsFragment), integrated in
// closed form with the depths spread evenly (a box) around their mean. Reference: k x k
// stratified lines, not randomised: the converged value of the lines' estimate.
//
// kMomentsFragment: (distance, distance^2) per scene texel, level 0 of the moments' mip chain.
//
// kBlur: one direction of a separable 5-tap filter that averages the 4-pixel rotation pattern
// exactly (weights 1/2, 1, 1, 1, 1/2), each tap weighted down by its
// depth difference relative to the centre's distance and by the angle between the normals. It
// reads only the estimate's output, (open, distance, normal x, normal y): one fetch per tap.
//
// kCompositeFragment: the obscurance scaled by strength, written for multiplicative blending
// over the scene colour, or (u_copy) the scene colour times it written elsewhere; or the
// obscurance shown alone. A half-resolution result is upsampled by depth (the texels'
// distances), so it does not bleed across silhouettes.
#pragma once

namespace nq::npr::obscurance {

inline constexpr int kComputeGroupSize = 8;  // kComputeMain's local size each way (VO_GROUP)

extern const char* const kFullscreenVertex;
extern const char* const kSceneLibrary;  // depth to distance, projection, normals
extern const char* const kEstimate;      // pass_result(pixel)
extern const char* const kMomentsFragment;
extern const char* const kBlur;  // pass_result(pixel)
extern const char* const kCompositeFragment;
extern const char* const kFragmentHeader;  // #version 330 core
extern const char* const kComputeHeader;   // #version 430 core
extern const char* const kFragmentMain;    // pass_result at gl_FragCoord into output 0
extern const char* const kComputeMain;     // pass_result into image unit 0 (u_target)

}  // namespace nq::npr::obscurance
