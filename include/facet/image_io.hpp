// Writing rendered images to disk: PNG (libpng) and binary PPM (P6), chosen by extension.
// Files are written to a temporary name and renamed, so a failed write leaves nothing behind;
// a path that is a symbolic link is written through: the file it points to is replaced.
#pragma once

#include <cstdio>
#include <string>

#include "facet/framebuffer.hpp"

namespace facet {

enum class ImageFileType { png, ppm };

// The type for a path's extension (.png, .ppm, case-insensitive); throws facet::Error otherwise.
ImageFileType image_file_type(const std::string& path);

// Throws facet::Error (naming the path) if the directory does not exist or is not writable.
void check_writable(const std::string& path);

// The file a write to `path` replaces: `path` itself, or, if it is a symbolic link, the file
// the link points to (followed link by link; a dangling link gives the file to create). A
// writer renames its temporary file onto this, in this file's folder, so the link stays a link.
// Throws facet::Error naming the path if the links loop or nest deeper than 40 (Linux's limit).
std::string write_target(const std::string& path);

// Writes the framebuffer's color as 8-bit sRGB (PNG keeps alpha; PPM drops it).
void write_image(const Framebuffer& framebuffer, const std::string& path);

// The same encoded into a file the caller opened (and later checks, closes and renames), for
// writers that manage their own temporary files; `name` is the file named in errors.
void write_image(const Framebuffer& framebuffer, ImageFileType type, std::FILE* file,
                 const std::string& name);

}  // namespace facet
