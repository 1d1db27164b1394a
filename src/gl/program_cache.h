#pragma once
// Programs built on first use per set of #define variants, so a pass can switch variants
// (border mode, kernel size) without recompiling every frame.
#include <map>
#include <string>
#include <vector>

#include "gl/shader_library.h"

namespace cutaway::gl {

class ProgramCache {
public:
    ProgramCache(const ShaderLibrary& shaders, std::vector<ShaderStage> stages)
        : shaders_(&shaders), stages_(std::move(stages)) {}

    const Program& get(const ShaderDefines& defines) {
        std::string key;
        for (const auto& [name, value] : defines) key += name + "=" + value + ";";
        auto found = programs_.find(key);
        if (found == programs_.end()) found = programs_.emplace(key, shaders_->build(stages_, defines)).first;
        return found->second;
    }

private:
    const ShaderLibrary* shaders_;
    std::vector<ShaderStage> stages_;
    std::map<std::string, Program> programs_;
};

}  // namespace cutaway::gl
