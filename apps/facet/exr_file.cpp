// OpenEXR files (see exr_file.hpp).
#include "exr_file.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <exception>

#include "facet/error.hpp"

namespace facet::cli {

void write_exr(const std::string& path, const std::string& name, int width, int height,
               const std::vector<ExrChannel>& channels) {
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    for (const ExrChannel& channel : channels) {
      Imf::PixelType type = channel.is_uint ? Imf::UINT : Imf::FLOAT;
      header.channels().insert(channel.name, Imf::Channel(type));
      // Both types are 4 bytes wide.
      std::size_t x_stride = 4 * static_cast<std::size_t>(channel.values_per_pixel);
      std::size_t y_stride = x_stride * static_cast<std::size_t>(width);
      frame.insert(channel.name,
                   Imf::Slice(type, static_cast<char*>(const_cast<void*>(channel.first)), x_stride,
                              y_stride));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw Error(name + ": cannot write the OpenEXR file (" + e.what() + ")");
  }
}

}  // namespace facet::cli
