#include "gltf/meshopt_decode.h"

#include <meshoptimizer.h>

#include "util/error.h"

namespace vkpt::internal {

std::string CheckMeshoptStream(const MeshoptStream& s) {
  const std::string stride = "byteStride " + std::to_string(s.byteStride);
  if (s.count == 0) return "count is 0";
  if (s.mode == "ATTRIBUTES") {
    if (s.byteStride == 0 || s.byteStride % 4 || s.byteStride > 256)
      return stride + " is not a multiple of 4 in [4, 256] for ATTRIBUTES";
  } else if (s.mode == "TRIANGLES" || s.mode == "INDICES") {
    if (s.byteStride != 2 && s.byteStride != 4) return stride + " is not 2 or 4 for " + s.mode;
    if (s.mode == "TRIANGLES" && s.count % 3) return "count " + std::to_string(s.count) + " is not a multiple of 3";
    if (s.filter != "NONE") return "filter " + s.filter + " applies only to ATTRIBUTES";
  } else {
    return "mode \"" + s.mode + "\" is not ATTRIBUTES, TRIANGLES or INDICES";
  }
  if (s.filter == "OCTAHEDRAL") {
    if (s.byteStride != 4 && s.byteStride != 8) return stride + " is not 4 or 8 for the OCTAHEDRAL filter";
  } else if (s.filter == "QUATERNION") {
    if (s.byteStride != 8) return stride + " is not 8 for the QUATERNION filter";
  } else if (s.filter != "NONE" && s.filter != "EXPONENTIAL") {
    return "filter \"" + s.filter + "\" is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL";
  }
  return "";
}

void DecodeMeshoptStream(std::span<const unsigned char> encoded, const MeshoptStream& s, std::span<unsigned char> out) {
  if (std::string problem = CheckMeshoptStream(s); !problem.empty() || out.size() != s.count * s.byteStride)
    throw Error("EXT_meshopt_compression: " + (problem.empty() ? "output size disagrees with count" : problem));
  int status = 0;
  if (s.mode == "ATTRIBUTES")
    status = meshopt_decodeVertexBuffer(out.data(), s.count, s.byteStride, encoded.data(), encoded.size());
  else if (s.mode == "TRIANGLES")
    status = meshopt_decodeIndexBuffer(out.data(), s.count, s.byteStride, encoded.data(), encoded.size());
  else status = meshopt_decodeIndexSequence(out.data(), s.count, s.byteStride, encoded.data(), encoded.size());
  if (status != 0)
    throw Error("EXT_meshopt_compression: the " + s.mode + " data (" + std::to_string(encoded.size()) +
                " bytes) is malformed (meshoptimizer error " + std::to_string(status) + ")");
  // The filters work in place on the decoded elements (their inverses ran before encoding).
  if (s.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), s.count, s.byteStride);
  if (s.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), s.count, s.byteStride);
  if (s.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), s.count, s.byteStride);
}

}  // namespace vkpt::internal
