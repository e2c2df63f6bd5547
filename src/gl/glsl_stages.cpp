// GLSL vertex and geometry stages (see glsl_sources.hpp). Both write the same Varyings block,
// so the fragment stage reads one layout: facet's surface layout (shading/surface.hpp) plus
// Gouraud's interpolated light.
#include "gl/glsl_sources.hpp"

namespace facet::gl {

const char* const kVertexGlsl = R"glsl(
// Attributes a mesh does not have keep a constant value (gpu_meshes.cpp sets it): normal and
// tangent zero, color white, texture coordinate (0, 0), as facet's vertex stage gives them.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_tangent;

uniform mat4 u_model;
uniform mat4 u_model_view_projection;
uniform mat3 u_normal_matrix;  // inverse transpose of the model matrix's 3x3
uniform vec4 u_base_color;
uniform bool u_use_vertex_colors;
uniform bool u_has_normals;
uniform float u_point_size;

out Varyings VARYINGS out_v;

void main() {
  gl_Position = u_model_view_projection * vec4(a_position, 1.0);
  gl_PointSize = u_point_size;
  out_v.texcoord = a_texcoord;
  out_v.color = u_use_vertex_colors ? u_base_color * a_color : u_base_color;
  out_v.normal = safe_normalize(u_normal_matrix * a_normal);
  out_v.position = (u_model * vec4(a_position, 1.0)).xyz;
  out_v.tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w);
  out_v.diffuse = out_v.specular = vec3(0.0);
#ifdef MODEL_GOURAUD
  // A mesh without normals is lit per face instead, in the geometry stage.
  if (u_has_normals) gouraud_light(out_v.position, out_v.normal, out_v.diffuse, out_v.specular);
#endif
}
)glsl";

// Per triangle, what facet does at primitive assembly and setup (pipeline/geometry/primitive.cpp,
// pipeline/setup/back_faces.hpp): the face normal where the mesh has none, flat shading's one
// color, and whether the vertex normals agree with the winding (for two-sided lighting). Lines
// and points pass through.
const char* const kGeometryGlsl = R"glsl(
#if defined(PRIMITIVE_POINTS)
layout(points) in;
layout(points, max_vertices = 1) out;
#define CORNERS 1
#elif defined(PRIMITIVE_LINES)
layout(lines) in;
layout(line_strip, max_vertices = 2) out;
#define CORNERS 2
#else
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
#define CORNERS 3
#endif

in Varyings VARYINGS in_v[];

out Varyings VARYINGS out_v;

// Whether the vertex normals point to the side the triangle's winding calls its front; the
// fragment stage compares it with gl_FrontFacing (back_faces.hpp's reverses_normal).
flat out int normals_front;
flat out vec4 face_color;  // flat shading's lit color
// The wire overlay: the three edges as lines of the window, a x + b y + c = 0. Made from the
// homogeneous window positions (x w, y w, w), so they are right even for a triangle with a
// corner behind the eye, whose window positions alone would not be (Olano and Greer 1997).
flat out vec3 edge_lines[3];
uniform vec2 u_viewport;

uniform bool u_has_normals;
uniform float u_model_handedness;  // sign of the model matrix's determinant

void main() {
  vec3 normals[CORNERS];
  for (int i = 0; i < CORNERS; ++i) normals[i] = in_v[i].normal;
  vec3 diffuse[CORNERS], specular[CORNERS];
  for (int i = 0; i < CORNERS; ++i) diffuse[i] = in_v[i].diffuse, specular[i] = in_v[i].specular;
  // Flat outputs are written with every vertex emitted (outputs are undefined after EmitVertex).
  int front = 1;
  vec4 face = in_v[0].color;
#if !defined(PRIMITIVE_POINTS) && !defined(PRIMITIVE_LINES)
  vec3 p0 = in_v[0].position, p1 = in_v[1].position, p2 = in_v[2].position;
  vec3 winding = cross(p1 - p0, p2 - p0);
  // facet transforms the object-space cross product by the normal matrix; that is the world
  // cross product divided by the determinant, so the same direction up to its sign.
  vec3 face_normal = safe_normalize(winding) * u_model_handedness;
  vec3 centre = (p0 + p1 + p2) / 3.0;
  if (!u_has_normals) {
    for (int i = 0; i < 3; ++i) normals[i] = face_normal;
#ifdef MODEL_GOURAUD
    for (int i = 0; i < 3; ++i) gouraud_light(centre, face_normal, diffuse[i], specular[i]);
#endif
  }
  front = dot(normals[0] + normals[1] + normals[2], winding) >= 0.0 ? 1 : 0;
#ifdef MODEL_FLAT
  vec4 average = (in_v[0].color + in_v[1].color + in_v[2].color) / 3.0;
  face = vec4(diffuse_light(average.rgb, face_normal, centre), average.a);
#endif
#endif
  vec3 lines[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
#if defined(WIRE_OVERLAY) && !defined(PRIMITIVE_POINTS) && !defined(PRIMITIVE_LINES)
  vec3 h[3];
  for (int i = 0; i < 3; ++i) {
    vec4 c = gl_in[i].gl_Position;
    h[i] = vec3((c.xy * 0.5 + 0.5 * c.w) * u_viewport, c.w);
  }
  for (int i = 0; i < 3; ++i) lines[i] = cross(h[(i + 1) % 3], h[(i + 2) % 3]);
#endif
  for (int i = 0; i < CORNERS; ++i) {
    gl_Position = gl_in[i].gl_Position;
    edge_lines = lines;
    gl_PointSize = gl_in[i].gl_PointSize;
    out_v.texcoord = in_v[i].texcoord;
    out_v.color = in_v[i].color;
    out_v.normal = normals[i];
    out_v.position = in_v[i].position;
    out_v.tangent = in_v[i].tangent;
    out_v.diffuse = diffuse[i];
    out_v.specular = specular[i];
    normals_front = front;
    face_color = face;
    EmitVertex();
  }
  EndPrimitive();
}
)glsl";

}  // namespace facet::gl
