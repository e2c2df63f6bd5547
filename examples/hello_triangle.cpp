// hello_triangle: the smallest complete facet program — one triangle with a red, a green and a
// blue corner, rendered on the CPU and written to a PNG. Usage: hello_triangle [out.png]
#include <cstdio>
#include <exception>
#include <facet/facet.hpp>

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : "hello_triangle.png";
  try {
    // One triangle, counter-clockwise as seen from the camera (front faces are CCW).
    facet::Mesh triangle;
    triangle.positions = {{-1.0f, -0.8f, 0.0f}, {1.0f, -0.8f, 0.0f}, {0.0f, 0.9f, 0.0f}};
    triangle.colors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};  // linear RGBA per vertex

    // RGBA8 sRGB color + float depth (facet::DepthImage::none as a 4th argument: color only,
    // faster when nothing reads the depth back)
    facet::Framebuffer image(640, 480);
    facet::Camera camera = facet::Camera::look_at(/*eye=*/{0, 0, 2.5f}, /*target=*/{0, 0, 0},
                                                  /*up=*/{0, 1, 0}, /*fov_y_degrees=*/60.0f,
                                                  /*aspect=*/640.0f / 480.0f);

    facet::Renderer renderer;  // all cores, 64x64 tiles, black background
    renderer.begin_frame(camera);
    facet::Material material;
    material.shading = facet::ShadingModel::vertex_color;
    renderer.draw(triangle, material);
    renderer.finish(image);

    facet::write_image(image, path);  // .png or .ppm, by extension
    std::printf("wrote %s (%dx%d)\n", path, image.width(), image.height());
    return 0;
  } catch (const std::exception& e) {  // facet::Error: one line saying what went wrong
    std::fprintf(stderr, "hello_triangle: %s\n", e.what());
    return 1;
  }
}
