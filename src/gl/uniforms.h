#pragma once
// Typed uniform setters on a program object (direct state access, no glUseProgram needed).
// A name the linker dropped (location -1) is ignored, as GL itself does.
#include <glm/glm.hpp>

#include "gl/gl_objects.h"

namespace cutaway::gl {

inline void set_uniform(const Program& p, const char* name, float v) { glProgramUniform1f(p.id(), p.uniform(name), v); }
inline void set_uniform(const Program& p, const char* name, int v) { glProgramUniform1i(p.id(), p.uniform(name), v); }
inline void set_uniform(const Program& p, const char* name, unsigned v) { glProgramUniform1ui(p.id(), p.uniform(name), v); }
inline void set_uniform(const Program& p, const char* name, bool v) { glProgramUniform1i(p.id(), p.uniform(name), v ? 1 : 0); }
inline void set_uniform(const Program& p, const char* name, const glm::vec2& v) {
    glProgramUniform2f(p.id(), p.uniform(name), v.x, v.y);
}
inline void set_uniform(const Program& p, const char* name, const glm::ivec2& v) {
    glProgramUniform2i(p.id(), p.uniform(name), v.x, v.y);
}
inline void set_uniform(const Program& p, const char* name, const glm::uvec2& v) {
    glProgramUniform2ui(p.id(), p.uniform(name), v.x, v.y);
}
inline void set_uniform(const Program& p, const char* name, const glm::ivec3& v) {
    glProgramUniform3i(p.id(), p.uniform(name), v.x, v.y, v.z);
}
inline void set_uniform(const Program& p, const char* name, const glm::uvec3& v) {
    glProgramUniform3ui(p.id(), p.uniform(name), v.x, v.y, v.z);
}
inline void set_uniform(const Program& p, const char* name, const glm::vec3& v) {
    glProgramUniform3f(p.id(), p.uniform(name), v.x, v.y, v.z);
}
inline void set_uniform(const Program& p, const char* name, const glm::vec4& v) {
    glProgramUniform4f(p.id(), p.uniform(name), v.x, v.y, v.z, v.w);
}
inline void set_uniform(const Program& p, const char* name, const glm::mat4& m) {
    glProgramUniformMatrix4fv(p.id(), p.uniform(name), 1, GL_FALSE, &m[0][0]);
}

}  // namespace cutaway::gl
