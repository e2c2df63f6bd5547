// Image-based lighting (Environment::image_based_lighting): the environment as the light that
// reaches a physically based surface from every direction, for lit_models.hpp's PBR model.
// Diffuse: the irradiance, from the environment's first nine spherical harmonics (Ramamoorthi
// and Hanrahan, "An Efficient Representation for Irradiance Environment Maps", 2001), exact
// for any light that varies linearly with direction and within a few percent for real skies.
// Specular: the split sum (Karis, "Real Shading in Unreal Engine 4", 2013) with the
// environment blurred by roughness through its mip levels and Karis' analytic fit of the BRDF's
// integral (the mobile "EnvBRDFApprox").
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "facet/light.hpp"
#include "shading/pbr_surface.hpp"

namespace facet::shading {

// The environment's radiance projected on the real spherical harmonics of bands 0 to 2, in the
// order (0,0), (1,-1), (1,0), (1,1), (2,-2), (2,-1), (2,0), (2,1), (2,2).
using IrradianceHarmonics = std::array<glm::vec3, 9>;

// Projects the environment (its image at a coarse mip level, or the sky gradient with SIMD:
// sky_batch.hpp), integrating over a 64 x 32 grid of directions weighted by their solid angles.
IrradianceHarmonics project_environment(const Environment& environment);

// The irradiance on a surface of unit normal n: pi times the radiance of a uniform environment.
glm::vec3 irradiance(const IrradianceHarmonics& harmonics, glm::vec3 n);

// The scale and bias of f0 in the split sum's BRDF integral at this n . v and roughness.
struct SpecularIntegral {
  float scale, bias;
};
SpecularIntegral specular_integral(float n_dot_v, float roughness);

// The light a physically based surface (PbrSurface, pbr_surface.hpp; f0 its reflectance at normal
// incidence) takes from the environment at unit normal n seen from unit direction v: the
// irradiance through the diffuse albedo, and the split sum's specular from `seen`, the radiance
// along the mirror direction `mirror` (glm::reflect(-v, n)) blurred by roughness (the shading
// kernel's lookup: environment_batch-inl.h), moving toward the irradiance around that direction
// (a cosine lobe, the widest GGX lobe's shape) as the surface roughens.
glm::vec3 environment_light(const IrradianceHarmonics& light, const PbrSurface& surface,
                            glm::vec3 f0, glm::vec3 n, glm::vec3 v, glm::vec3 mirror,
                            glm::vec3 seen);

}  // namespace facet::shading
