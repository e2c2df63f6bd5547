// Writing rendered images to disk: PNG (libpng) and binary PPM (P6), chosen by extension.
// Files are written to a temporary name and renamed, so a failed write leaves nothing behind.
#pragma once

#include <string>

#include "facet/framebuffer.hpp"

namespace facet {

enum class ImageFileType { png, ppm };

// The type for a path's extension (.png, .ppm, case-insensitive); throws facet::Error otherwise.
ImageFileType image_file_type(const std::string& path);

// Throws facet::Error (naming the path) if the directory does not exist or is not writable.
void check_writable(const std::string& path);

// Writes the framebuffer's color as 8-bit sRGB (PNG keeps alpha; PPM drops it).
void write_image(const Framebuffer& framebuffer, const std::string& path);

}  // namespace facet
