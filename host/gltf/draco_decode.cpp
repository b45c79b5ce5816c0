#include "gltf/draco_decode.h"

#include <draco/compression/decode.h>
#include <draco/compression/point_cloud/point_cloud_decoder.h>
#include <draco/core/decoder_buffer.h>
#include <draco/core/varint_decoding.h>
#include <draco/metadata/metadata_decoder.h>

#include <cstring>
#include <memory>

#include "util/error.h"

namespace vkpt::internal {
namespace {

[[noreturn]] void Fail(const std::string& what) { throw Error("KHR_draco_mesh_compression: " + what); }

// The attribute's value at every point, converted to OutT, appended to `out`.
template <class OutT>
void Convert(const draco::PointAttribute& a, const draco::Mesh& mesh, const DracoAccessor& acc,
             std::vector<unsigned char>& out) {
  out.resize(acc.count * acc.components * sizeof(OutT));
  OutT value[4];
  for (uint32_t p = 0; p < mesh.num_points(); ++p) {
    if (!a.ConvertValue<OutT>(a.mapped_index(draco::PointIndex(p)), int8_t(acc.components), value))
      Fail("attribute " + acc.attribute + " has no value for point " + std::to_string(p));
    std::memcpy(out.data() + size_t(p) * acc.components * sizeof(OutT), value, acc.components * sizeof(OutT));
  }
}

// libdraco sizes its arrays from the triangle count a bitstream declares and checks it
// only against other counts of the same stream: 579 bytes can claim 1.4 G triangles and
// have it reserve 5.7 GB. So the header and connectivity counts are read first (the
// layout of bitstream 2.2, which the extension requires: header, optional metadata, then
// for edgebreaker a traversal byte and varints of vertices and faces, for sequential
// varints of faces and points) and the faces must be the indices accessor's, which the
// memory budget was charged for.
void CheckDeclaredCounts(std::span<const unsigned char> bitstream, size_t indexCount) {
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bitstream.data()), bitstream.size());
  draco::DracoHeader header;
  if (const draco::Status status = draco::PointCloudDecoder::DecodeHeader(&buffer, &header); !status.ok())
    Fail("the data (" + std::to_string(bitstream.size()) + " bytes) is not Draco: " + status.error_msg_string());
  if (header.version_major != 2 || header.version_minor != 2)
    Fail("the data is Draco bitstream " + std::to_string(header.version_major) + "." +
         std::to_string(header.version_minor) + "; the extension requires 2.2");
  if (header.encoder_type != draco::TRIANGULAR_MESH) Fail("the data holds a point cloud, not a triangle mesh");
  if (header.flags & METADATA_FLAG_MASK) {
    draco::MetadataDecoder metadata;
    draco::GeometryMetadata skipped;
    if (!metadata.DecodeGeometryMetadata(&buffer, &skipped)) Fail("the data's metadata is malformed");
  }
  uint32_t faces = 0, other = 0;
  bool read = false;
  if (header.encoder_method == draco::MESH_EDGEBREAKER_ENCODING) {
    uint8_t traversal = 0;
    read = buffer.Decode(&traversal) && draco::DecodeVarint(&other, &buffer) && draco::DecodeVarint(&faces, &buffer);
  } else if (header.encoder_method == draco::MESH_SEQUENTIAL_ENCODING) {
    read = draco::DecodeVarint(&faces, &buffer) && draco::DecodeVarint(&other, &buffer);
  } else {
    Fail("the data's encoding method " + std::to_string(header.encoder_method) +
         " is neither sequential nor edgebreaker");
  }
  if (!read) Fail("the data ends inside its connectivity header");
  if (uint64_t(faces) * 3 != indexCount)
    Fail("the data declares " + std::to_string(faces) + " triangles, but the indices accessor has " +
         std::to_string(indexCount) + " indices");
}

// The Draco types a glTF accessor can take values from (DT_BOOL, DT_INT64 and others
// cannot be converted safely: a "bool" byte of 255 is undefined behaviour to read).
bool IsGltfDataType(draco::DataType t) {
  return t == draco::DT_INT8 || t == draco::DT_UINT8 || t == draco::DT_INT16 || t == draco::DT_UINT16 ||
         t == draco::DT_INT32 || t == draco::DT_UINT32 || t == draco::DT_FLOAT32;
}

}  // namespace

DracoPrimitive DecodeDraco(std::span<const unsigned char> bitstream, const std::vector<DracoAccessor>& accessors,
                           size_t indexCount) {
  CheckDeclaredCounts(bitstream, indexCount);
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bitstream.data()), bitstream.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) Fail("the data is malformed (draco: " + decoded.status().error_msg_string() + ")");
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();

  DracoPrimitive out;
  if (uint64_t(mesh->num_faces()) * 3 != indexCount)
    Fail("the data holds " + std::to_string(mesh->num_faces()) + " triangles, but the indices accessor has " +
         std::to_string(indexCount) + " indices");
  out.indices.reserve(indexCount);
  for (uint32_t f = 0; f < mesh->num_faces(); ++f)
    for (draco::PointIndex p : mesh->face(draco::FaceIndex(f))) out.indices.push_back(p.value());
  for (const DracoAccessor& acc : accessors) {
    const draco::PointAttribute* a = mesh->GetAttributeByUniqueId(acc.uniqueId);
    if (!a) Fail("attribute " + acc.attribute + ": the data has no attribute with id " + std::to_string(acc.uniqueId));
    if (!IsGltfDataType(a->data_type()))
      Fail("attribute " + acc.attribute + " has Draco data type " + std::to_string(int(a->data_type())) +
           ", which no glTF accessor holds");
    if (a->num_components() != acc.components)
      Fail("attribute " + acc.attribute + " has " + std::to_string(a->num_components()) +
           " components in the data, but its accessor has " + std::to_string(acc.components));
    if (mesh->num_points() != acc.count)
      Fail("the data holds " + std::to_string(mesh->num_points()) + " points, but the " + acc.attribute +
           " accessor has " + std::to_string(acc.count));
    std::vector<unsigned char>& bytes = out.attributes.emplace_back();
    switch (acc.componentType) {
      case 5120: Convert<int8_t>(*a, *mesh, acc, bytes); break;
      case 5121: Convert<uint8_t>(*a, *mesh, acc, bytes); break;
      case 5122: Convert<int16_t>(*a, *mesh, acc, bytes); break;
      case 5123: Convert<uint16_t>(*a, *mesh, acc, bytes); break;
      case 5125: Convert<uint32_t>(*a, *mesh, acc, bytes); break;
      case 5126: Convert<float>(*a, *mesh, acc, bytes); break;
      default: Fail("attribute " + acc.attribute + ": component type " + std::to_string(acc.componentType));
    }
  }
  return out;
}

}  // namespace vkpt::internal
