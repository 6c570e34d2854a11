#include "protocol.h"

#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace raylab::grading::protocol {
namespace {

// Reads exactly `size` bytes; returns how many it got before end of file.
std::size_t read_fully(int fd, char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, data + done, size - done);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "read");
    }
    done += static_cast<std::size_t>(n);
  }
  return done;
}

}  // namespace

const char* function_name(Function function) {
  switch (function) {
    case Function::GenerateCameraRay: return "generate_camera_ray";
    case Function::IntersectRaySphere: return "intersect_ray_sphere";
    case Function::IntersectRayTriangle: return "intersect_ray_triangle";
    case Function::IntersectRayTriangleWatertight: return "intersect_ray_triangle_watertight";
    case Function::IntersectRayBox: return "intersect_ray_box";
    case Function::BuildBvh: return "build_bvh";
    case Function::BuildBvhSah: return "build_bvh_sah";
    case Function::IntersectBvh: return "intersect_bvh";
    case Function::RenderStageImage: return "rendering the stage's picture";
    case Function::TrianglesHit: return "intersect_ray_triangle";
    case Function::WarpSamples: return "a stage-07 warp (sample_...)";
    case Function::WarpPdfs: return "a stage-07 density (..._pdf)";
  }
  return "a stage function";
}

bool read_frame(int fd, std::string& payload) {
  unsigned char header[4];
  const std::size_t got = read_fully(fd, reinterpret_cast<char*>(header), 4);
  if (got == 0) return false;
  if (got < 4) throw ProtocolError("a frame cut short");
  const std::uint32_t size = header[0] | header[1] << 8 | header[2] << 16 | std::uint32_t(header[3]) << 24;
  if (size > kMaxFrameBytes) throw ProtocolError("a frame of " + std::to_string(size) + " bytes (too large)");
  payload.resize(size);
  if (read_fully(fd, payload.data(), size) < size) throw ProtocolError("a frame cut short");
  return true;
}

void write_frame(int fd, const std::string& payload) {
  const auto size = static_cast<std::uint32_t>(payload.size());
  std::string frame;
  frame.reserve(4 + payload.size());
  for (int i = 0; i < 4; ++i) frame.push_back(static_cast<char>((size >> (8 * i)) & 0xff));
  frame += payload;
  std::size_t done = 0;
  while (done < frame.size()) {
    const ssize_t n = ::write(fd, frame.data() + done, frame.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "write");
    }
    done += static_cast<std::size_t>(n);
  }
}

void put_lists(Writer& out, const std::vector<std::vector<std::uint32_t>>& lists) {
  std::vector<std::uint64_t> offsets{0};
  std::vector<std::uint32_t> values;
  for (const auto& list : lists) {
    values.insert(values.end(), list.begin(), list.end());
    offsets.push_back(values.size());
  }
  out.put_vector(offsets);
  out.put_vector(values);
}

std::vector<std::vector<std::uint32_t>> get_lists(Reader& in) {
  const auto offsets = in.get_vector<std::uint64_t>();
  const auto values = in.get_vector<std::uint32_t>();
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != values.size()) throw ProtocolError("malformed lists");
  std::vector<std::vector<std::uint32_t>> lists(offsets.size() - 1);
  for (std::size_t i = 0; i + 1 < offsets.size(); ++i) {
    if (offsets[i + 1] < offsets[i] || offsets[i + 1] > values.size()) throw ProtocolError("malformed lists");
    lists[i].assign(values.begin() + static_cast<std::ptrdiff_t>(offsets[i]), values.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1]));
  }
  return lists;
}

}  // namespace raylab::grading::protocol
