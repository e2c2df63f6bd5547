// The GLSL of the GL twin, as C++ strings: each is facet's own shading code (src/shading/)
// written again in GLSL, operation for operation where GLSL allows. Program (gl_program.hpp)
// puts "#version 330 core", the draw's #defines and kCommonGlsl in front of a stage.
//
//   kCommonGlsl     lights (light_batch-inl.h), BRDFs (shade_batch.cpp), environment
//                   (environment.cpp),
//                   shared by every stage: Gouraud lights vertices, flat shading lights faces
//   kVertexGlsl     the vertex stage: world position, normal, tangent, material color
//   kGeometryGlsl   per triangle: face normals, flat color, which side of the surface is seen
//   kFragmentGlsl   the shading models and fog (shade_batch.cpp), alpha mask
//   kSkyVertexGlsl, kSkyFragmentGlsl   the background (pipeline/output/sky_row.cpp)
#pragma once

namespace facet::gl {

extern const char* const kCommonGlsl;
extern const char* const kVertexGlsl;
extern const char* const kGeometryGlsl;
extern const char* const kFragmentGlsl;
extern const char* const kSkyVertexGlsl;
extern const char* const kSkyFragmentGlsl;

// The most lights a frame may have: the uniform arrays are this long.
inline constexpr int kMaxLights = 32;

}  // namespace facet::gl
