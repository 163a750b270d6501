#include "gi/core/kernel_bindings.h"

#include "rhi/rhi.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

namespace lumina::gi {

namespace {

// The few SPIR-V opcodes, decorations and storage classes a binding check needs (SPIR-V spec,
// sections 3.x): names, bindings, and the types that tell a texture from a buffer.
constexpr uint32_t kMagic = 0x07230203u;
constexpr uint32_t kHeaderWords = 5;
constexpr uint32_t kOpName = 5;
constexpr uint32_t kOpTypeImage = 25;
constexpr uint32_t kOpTypeSampler = 26;
constexpr uint32_t kOpTypeSampledImage = 27;
constexpr uint32_t kOpTypeArray = 28;
constexpr uint32_t kOpTypeRuntimeArray = 29;
constexpr uint32_t kOpTypeStruct = 30;
constexpr uint32_t kOpTypePointer = 32;
constexpr uint32_t kOpVariable = 59;
constexpr uint32_t kOpDecorate = 71;
constexpr uint32_t kDecorationBlock = 2;
constexpr uint32_t kDecorationBufferBlock = 3;
constexpr uint32_t kDecorationBinding = 33;
constexpr uint32_t kDecorationDescriptorSet = 34;
constexpr uint32_t kStorageClassStorageBuffer = 12;
constexpr uint32_t kDimBuffer = 5;
constexpr uint32_t kImageSampledStorage = 2;

// The build's binding shifts (cmake/LuminaShaders.cmake, docs/binding.md).
constexpr uint32_t kShiftT = 100;
constexpr uint32_t kShiftU = 200;
constexpr uint32_t kShiftS = 300;

struct Type {
    uint32_t opcode = 0;
    std::vector<uint32_t> operands; // after the result id
};

std::string literalString(std::span<const uint32_t> words) {
    std::string out;
    for (uint32_t word : words) {
        for (int byte = 0; byte < 4; ++byte) {
            const char c = char((word >> (8 * byte)) & 0xffu);
            if (c == '\0') {
                return out;
            }
            out += c;
        }
    }
    return out;
}

const char* kindName(KernelResourceKind kind) {
    switch (kind) {
    case KernelResourceKind::ConstantBuffer:
        return "a constant buffer";
    case KernelResourceKind::Texture:
        return "a texture";
    case KernelResourceKind::Buffer:
        return "a buffer";
    case KernelResourceKind::StorageTexture:
        return "a storage texture";
    case KernelResourceKind::Sampler:
        return "a sampler";
    }
    return "a resource";
}

KernelResourceKind kindOf(rhi::BindingType type) {
    switch (type) {
    case rhi::BindingType::ConstantBuffer:
        return KernelResourceKind::ConstantBuffer;
    case rhi::BindingType::TextureSRV:
        return KernelResourceKind::Texture;
    case rhi::BindingType::TextureUAV:
        return KernelResourceKind::StorageTexture;
    case rhi::BindingType::BufferSRV:
    case rhi::BindingType::RawBufferSRV:
    case rhi::BindingType::BufferUAV:
    case rhi::BindingType::RawBufferUAV:
        return KernelResourceKind::Buffer;
    case rhi::BindingType::Sampler:
        return KernelResourceKind::Sampler;
    }
    return KernelResourceKind::ConstantBuffer;
}

std::string registerName(char registerClass, uint32_t reg, uint32_t space) {
    std::string out = std::string(1, registerClass) + std::to_string(reg);
    return space == 0 ? out : out + ", space" + std::to_string(space);
}

} // namespace

std::vector<KernelResource> kernelResources(std::string_view kernel, std::span<const uint32_t> spirv) {
    const auto malformed = [&](const std::string& why) {
        return rhi::Error("kernel '" + std::string(kernel) + "': SPIR-V " + why);
    };
    if (spirv.size() < kHeaderWords || spirv[0] != kMagic) {
        throw malformed("too short or without the SPIR-V magic number");
    }
    std::map<uint32_t, std::string> names;
    std::map<uint32_t, uint32_t> bindings, sets;
    std::map<uint32_t, bool> bufferBlocks; // struct id -> BufferBlock (true) or Block (false)
    std::map<uint32_t, Type> types;
    std::vector<std::pair<uint32_t, uint32_t>> variables; // (pointer type, id)
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t wordCount = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
        if (wordCount == 0 || at + wordCount > spirv.size()) {
            throw malformed("instruction at word " + std::to_string(at) + " runs past the end");
        }
        const std::span<const uint32_t> operands = spirv.subspan(at + 1, wordCount - 1);
        if (opcode == kOpName && operands.size() >= 2) {
            names[operands[0]] = literalString(operands.subspan(1));
        } else if (opcode == kOpDecorate && operands.size() >= 2) {
            if (operands[1] == kDecorationBinding && operands.size() >= 3) {
                bindings[operands[0]] = operands[2];
            } else if (operands[1] == kDecorationDescriptorSet && operands.size() >= 3) {
                sets[operands[0]] = operands[2];
            } else if (operands[1] == kDecorationBlock || operands[1] == kDecorationBufferBlock) {
                bufferBlocks[operands[0]] = operands[1] == kDecorationBufferBlock;
            }
        } else if ((opcode >= kOpTypeImage && opcode <= kOpTypeStruct) || opcode == kOpTypePointer) {
            if (!operands.empty()) {
                types[operands[0]] = {opcode, {operands.begin() + 1, operands.end()}};
            }
        } else if (opcode == kOpVariable && operands.size() >= 2) {
            variables.emplace_back(operands[0], operands[1]);
        }
        at += wordCount;
    }

    const auto typeOf = [&](uint32_t id) -> const Type& {
        const auto it = types.find(id);
        if (it == types.end()) {
            throw malformed("refers to a type %" + std::to_string(id) + " it does not declare");
        }
        return it->second;
    };
    std::vector<KernelResource> out;
    for (const auto& [pointerId, id] : variables) {
        const auto binding = bindings.find(id);
        if (binding == bindings.end()) {
            continue; // push constants, stage inputs and outputs, workgroup memory
        }
        const Type& pointer = typeOf(pointerId);
        if (pointer.opcode != kOpTypePointer || pointer.operands.size() < 2) {
            throw malformed("variable %" + std::to_string(id) + " is not of a pointer type");
        }
        const uint32_t storageClass = pointer.operands[0];
        uint32_t typeId = pointer.operands[1];
        const Type* type = &typeOf(typeId);
        while (type->opcode == kOpTypeArray || type->opcode == kOpTypeRuntimeArray ||
               type->opcode == kOpTypeSampledImage) {
            typeId = type->operands.at(0); // an array of resources: judge the element
            type = &typeOf(typeId);
        }
        KernelResource resource;
        const auto name = names.find(id);
        resource.name =
            name != names.end() && !name->second.empty() ? name->second : "%" + std::to_string(id);
        const auto set = sets.find(id);
        resource.space = set != sets.end() ? set->second : 0;
        const uint32_t b = binding->second;
        resource.registerClass = b >= kShiftS ? 's' : (b >= kShiftU ? 'u' : (b >= kShiftT ? 't' : 'b'));
        resource.reg = b - (b >= kShiftS ? kShiftS : (b >= kShiftU ? kShiftU : (b >= kShiftT ? kShiftT : 0)));
        if (type->opcode == kOpTypeSampler) {
            resource.kind = KernelResourceKind::Sampler;
        } else if (type->opcode == kOpTypeImage && type->operands.size() >= 6) {
            // operands: sampled type, Dim, Depth, Arrayed, MS, Sampled, ...
            resource.kind = type->operands[1] == kDimBuffer             ? KernelResourceKind::Buffer
                            : type->operands[5] == kImageSampledStorage ? KernelResourceKind::StorageTexture
                                                                        : KernelResourceKind::Texture;
        } else if (type->opcode == kOpTypeStruct) {
            const auto block = bufferBlocks.find(typeId);
            const bool storage =
                storageClass == kStorageClassStorageBuffer || (block != bufferBlocks.end() && block->second);
            resource.kind = storage ? KernelResourceKind::Buffer : KernelResourceKind::ConstantBuffer;
        } else {
            throw malformed("resource " + resource.name + " has a type this check does not know (opcode " +
                            std::to_string(type->opcode) + ")");
        }
        out.push_back(std::move(resource));
    }
    return out;
}

void checkKernelBindings(std::string_view kernel, const std::vector<KernelResource>& resources,
                         const SpaceBindings& bindings) {
    for (const KernelResource& resource : resources) {
        const std::string where = "kernel '" + std::string(kernel) + "' uses " + resource.name +
                                  " at register(" +
                                  registerName(resource.registerClass, resource.reg, resource.space) + ")";
        const rhi::BindingSetItem* bound = nullptr;
        std::string boundList;
        if (resource.space < bindings.size()) {
            for (const rhi::BindingSetItem& item : bindings[resource.space]) {
                const char itemClass = rhi::registerClass(item.type);
                boundList += (boundList.empty() ? "" : ", ") + registerName(itemClass, item.reg, 0);
                if (itemClass == resource.registerClass && item.reg == resource.reg) {
                    bound = &item;
                }
            }
        }
        if (!bound) {
            throw rhi::Error(where + ", but the pass binds nothing there (it binds " +
                             (boundList.empty() ? std::string("nothing") : boundList) + " in space " +
                             std::to_string(resource.space) + ")");
        }
        if (kindOf(bound->type) != resource.kind) {
            throw rhi::Error(where + ", which is " + kindName(resource.kind) + ", but the pass binds " +
                             kindName(kindOf(bound->type)) + " (" + rhi::bindingTypeName(bound->type) +
                             ") there");
        }
    }
}

std::vector<uint32_t> readKernelSpirv(const std::string& directory, std::string_view kernel) {
    const std::filesystem::path path = std::filesystem::path(directory) / (std::string(kernel) + ".spv");
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) {
        return {};
    }
    const auto bytes = size_t(file.tellg());
    if (bytes % sizeof(uint32_t) != 0) {
        throw rhi::Error("kernel '" + std::string(kernel) + "': " + path.string() + " is " +
                         std::to_string(bytes) + " bytes, not whole SPIR-V words");
    }
    std::vector<uint32_t> words(bytes / sizeof(uint32_t));
    file.seekg(0);
    file.read(reinterpret_cast<char*>(words.data()), std::streamsize(bytes));
    return words;
}

} // namespace lumina::gi
