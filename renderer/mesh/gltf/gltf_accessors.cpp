// The glTF reader: Every array of a glTF file is read through an accessor view checked here against its
// buffer view and buffer: offsets, strides, counts and component types.
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

Result<AccessorView> GltfReader::accessor(int index, const std::string& what, std::initializer_list<int> types) const {
  const std::string where = what + " (accessor " + std::to_string(index) + ")";
  if (index < 0 || index >= static_cast<int>(m_.accessors.size())) return fail(where + " does not exist");
  const tinygltf::Accessor& a = m_.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) return fail(where + " is sparse, which this viewer does not read");
  if (std::find(types.begin(), types.end(), a.type) == types.end()) return fail(where + " has the wrong type");
  AccessorView v;
  v.componentType = a.componentType;
  v.components = typeComponents(a.type);
  v.normalized = a.normalized;
  const int cb = componentBytes(a.componentType);
  if (cb == 0 || v.components == 0) return fail(where + " has an unknown component type");
  v.count = a.count;
  if (v.count == 0) return v;
  if (a.bufferView < 0 || a.bufferView >= static_cast<int>(m_.bufferViews.size()))
    return fail(where + " names no buffer view (buffer view " + std::to_string(a.bufferView) + ")");
  const tinygltf::BufferView& bv = m_.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (bv.buffer < 0 || bv.buffer >= static_cast<int>(m_.buffers.size()))
    return fail(where + ": its buffer view names buffer " + std::to_string(bv.buffer) + ", which does not exist");
  const std::vector<unsigned char>& buffer = m_.buffers[static_cast<std::size_t>(bv.buffer)].data;
  const std::uint64_t element = std::uint64_t(cb) * std::uint64_t(v.components);
  const std::uint64_t stride = bv.byteStride ? bv.byteStride : element;
  if (stride < element || stride > 252) return fail(where + ": byte stride " + std::to_string(bv.byteStride) + " is invalid");
  // All in 64 bits, and the count bounded by the view before multiplying.
  const std::uint64_t viewEnd = std::uint64_t(bv.byteOffset) + std::uint64_t(bv.byteLength);
  if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() || viewEnd > buffer.size())
    return fail(where + ": its buffer view (bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                ") runs past its buffer of " + std::to_string(buffer.size()) + " bytes");
  if (a.byteOffset > bv.byteLength || std::uint64_t(a.count) > bv.byteLength / stride + 1 ||
      std::uint64_t(a.byteOffset) + (std::uint64_t(a.count) - 1) * stride + element > bv.byteLength)
    return fail(where + ": " + std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                " run past its buffer view of " + std::to_string(bv.byteLength) + " bytes");
  v.data = buffer.data() + bv.byteOffset + a.byteOffset;
  v.stride = static_cast<std::size_t>(stride);
  return v;
}

Result<std::optional<AccessorView>> GltfReader::indices(const tinygltf::Primitive& prim, const std::string& where) const {
  if (prim.indices < 0) return std::optional<AccessorView>();
  Result<AccessorView> a = accessor(prim.indices, where + " indices", {TINYGLTF_TYPE_SCALAR});
  if (!a) return Error{a.error()};
  if (a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    return fail(where + ": indices must be unsigned integers");
  return std::optional<AccessorView>(*a);
}

}  // namespace npr::gltf
