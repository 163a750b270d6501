#include "gi/scene/gltf_accessor.h"

#include <algorithm>
#include <cstring>
#include <span>

namespace lumina::scene::gltf {

namespace {

int componentBytes(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

int typeComponents(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    default:
        return 0;
    }
}

const char* typeName(int components) {
    switch (components) {
    case 1:
        return "SCALAR";
    case 2:
        return "VEC2";
    case 3:
        return "VEC3";
    default:
        return "VEC4";
    }
}

// A strided run of elements inside one buffer, bounds already checked.
struct Span {
    const uint8_t* data = nullptr;
    size_t stride = 0;
};

// The bytes of `count` elements of `elementBytes` each, starting `offset` bytes into
// bufferView `viewIndex` (stride from the view when `useViewStride`).
Span viewSpan(const Context& context, int viewIndex, size_t offset, size_t count, size_t elementBytes,
              bool useViewStride, const std::string& what) {
    const tinygltf::Model& model = context.model;
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size()) {
        context.fail(what + ": bufferView " + std::to_string(viewIndex) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
        context.fail(what + ": bufferView " + std::to_string(viewIndex) + " names buffer " +
                     std::to_string(view.buffer) + ", which does not exist");
    }
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
        context.fail(what + ": bufferView " + std::to_string(viewIndex) + " (offset " +
                     std::to_string(view.byteOffset) + ", length " + std::to_string(view.byteLength) +
                     ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                     std::to_string(buffer.size()) + " bytes)");
    }
    size_t stride = elementBytes;
    if (useViewStride && view.byteStride != 0) {
        if (view.byteStride < elementBytes) {
            context.fail(what + ": bufferView " + std::to_string(viewIndex) + " has byteStride " +
                         std::to_string(view.byteStride) + ", less than the element size " +
                         std::to_string(elementBytes));
        }
        stride = view.byteStride;
    }
    // count <= kMaxAccessorElements and stride < 2^32, so this cannot overflow.
    const uint64_t needed = count == 0 ? 0 : uint64_t(count - 1) * stride + elementBytes;
    if (offset > view.byteLength || needed > view.byteLength - offset) {
        context.fail(what + ": " + std::to_string(count) + " elements of " + std::to_string(elementBytes) +
                     " bytes (stride " + std::to_string(stride) + ") at offset " + std::to_string(offset) +
                     " run past the end of bufferView " + std::to_string(viewIndex) + " (" +
                     std::to_string(view.byteLength) + " bytes)");
    }
    return {buffer.data() + view.byteOffset + offset, stride};
}

float readComponent(const uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float value;
        std::memcpy(&value, p, 4);
        return value;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto value = static_cast<int8_t>(*p);
        return normalized ? std::max(float(value) / 127.0f, -1.0f) : float(value);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t value;
        std::memcpy(&value, p, 2);
        return normalized ? std::max(float(value) / 32767.0f, -1.0f) : float(value);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t value;
        std::memcpy(&value, p, 2);
        return normalized ? float(value) / 65535.0f : float(value);
    }
    default: { // UNSIGNED_INT
        uint32_t value;
        std::memcpy(&value, p, 4);
        return float(value);
    }
    }
}

uint32_t readUnsigned(const uint8_t* p, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t value;
        std::memcpy(&value, p, 2);
        return value;
    }
    default: {
        uint32_t value;
        std::memcpy(&value, p, 4);
        return value;
    }
    }
}

const tinygltf::Accessor& checkedAccessor(const Context& context, int index, const std::string& what) {
    if (index < 0 || size_t(index) >= context.model.accessors.size()) {
        context.fail(what + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = context.model.accessors[size_t(index)];
    if (accessor.count > kMaxAccessorElements) {
        context.fail(what + ": accessor " + std::to_string(index) + " has " + std::to_string(accessor.count) +
                     " elements, more than the supported " + std::to_string(kMaxAccessorElements));
    }
    if (accessor.bufferView < 0 && accessor.count > kMaxUnbackedAccessorElements) {
        context.fail(what + ": accessor " + std::to_string(index) + " has no bufferView and " +
                     std::to_string(accessor.count) + " elements, more than the " +
                     std::to_string(kMaxUnbackedAccessorElements) + " allowed without data");
    }
    if (componentBytes(accessor.componentType) == 0) {
        context.fail(what + ": accessor " + std::to_string(index) + " has unknown componentType " +
                     std::to_string(accessor.componentType));
    }
    return accessor;
}

// Reads accessor `index` into `out` (count * components values) through `convert`, then
// applies its sparse substitutions.
template <typename T, typename Convert>
void readElements(const Context& context, int index, int components, const std::string& what,
                  std::vector<T>& out, Convert convert) {
    const tinygltf::Accessor& accessor = checkedAccessor(context, index, what);
    const size_t bytes = size_t(componentBytes(accessor.componentType));
    const size_t elementBytes = bytes * size_t(components);
    out.assign(accessor.count * size_t(components), T{});
    auto readRun = [&](Span span, size_t count, auto&& store) {
        for (size_t i = 0; i < count; ++i) {
            const uint8_t* element = span.data + i * span.stride;
            for (int c = 0; c < components; ++c) {
                store(i, c, convert(element + size_t(c) * bytes));
            }
        }
    };
    if (accessor.bufferView >= 0) {
        const Span span = viewSpan(context, accessor.bufferView, accessor.byteOffset, accessor.count,
                                   elementBytes, true, what);
        readRun(span, accessor.count,
                [&](size_t i, int c, T value) { out[i * size_t(components) + size_t(c)] = value; });
    } else if (!accessor.sparse.isSparse) {
        context.warn(what + ": accessor " + std::to_string(index) + " has no data; its values are all zero");
    }
    if (!accessor.sparse.isSparse) {
        return;
    }
    const auto& sparse = accessor.sparse;
    if (sparse.count < 0 || size_t(sparse.count) > accessor.count) {
        context.fail(what + ": accessor " + std::to_string(index) + " has " + std::to_string(sparse.count) +
                     " sparse values for " + std::to_string(accessor.count) + " elements");
    }
    const int indexType = sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        context.fail(what + ": accessor " + std::to_string(index) + " has sparse indices of componentType " +
                     std::to_string(indexType));
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        context.fail(what + ": accessor " + std::to_string(index) + " has a negative sparse byteOffset");
    }
    const size_t count = size_t(sparse.count);
    const Span indices = viewSpan(context, sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                                  count, size_t(componentBytes(indexType)), false, what + " sparse indices");
    const Span values = viewSpan(context, sparse.values.bufferView, size_t(sparse.values.byteOffset), count,
                                 elementBytes, false, what + " sparse values");
    std::vector<uint32_t> targets(count);
    for (size_t i = 0; i < count; ++i) {
        targets[i] = readUnsigned(indices.data + i * indices.stride, indexType);
        if (targets[i] >= accessor.count) {
            context.fail(what + ": accessor " + std::to_string(index) + " sparse index " +
                         std::to_string(targets[i]) + " is out of range (" + std::to_string(accessor.count) +
                         " elements)");
        }
    }
    readRun(values, count, [&](size_t i, int c, T value) {
        out[size_t(targets[i]) * size_t(components) + size_t(c)] = value;
    });
}

} // namespace

std::vector<float> readFloatAccessor(const Context& context, int index, int components,
                                     const std::string& what) {
    const tinygltf::Accessor& accessor = checkedAccessor(context, index, what);
    if (typeComponents(accessor.type) != components) {
        context.fail(what + ": accessor " + std::to_string(index) + " should be " + typeName(components) +
                     ", not type " + std::to_string(accessor.type));
    }
    std::vector<float> out;
    const int componentType = accessor.componentType;
    const bool normalized = accessor.normalized;
    readElements<float>(context, index, components, what, out,
                        [&](const uint8_t* p) { return readComponent(p, componentType, normalized); });
    return out;
}

std::vector<uint32_t> readIndexAccessor(const Context& context, int index, const std::string& what) {
    const tinygltf::Accessor& accessor = checkedAccessor(context, index, what);
    if (accessor.type != TINYGLTF_TYPE_SCALAR) {
        context.fail(what + ": index accessor " + std::to_string(index) + " is not SCALAR");
    }
    const int componentType = accessor.componentType;
    if (componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        context.fail(what + ": index accessor " + std::to_string(index) + " has componentType " +
                     std::to_string(componentType) + " (indices are unsigned byte, short or int)");
    }
    std::vector<uint32_t> out;
    readElements<uint32_t>(context, index, 1, what, out,
                           [&](const uint8_t* p) { return readUnsigned(p, componentType); });
    return out;
}

} // namespace lumina::scene::gltf
