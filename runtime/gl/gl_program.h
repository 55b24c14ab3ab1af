// Compiling and linking GLSL programs, and the full-screen pass they draw:
// one triangle covering the viewport, so a fragment shader runs once per
// pixel. Needs a current OpenGL 3.3 core context.
#pragma once

#include <string>

namespace skybake::gl {

// The vertex shader of the full-screen pass (GLSL 3.30 core).
extern const char* const kFullScreenVertexShader;

// A linked program, deleted with this object. Throws Error(Internal) with
// the compiler's log if the sources do not compile or link.
class GlProgram {
 public:
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  unsigned id() const { return program_; }

 private:
  unsigned program_ = 0;
};

// Draws the full-screen triangle with the current program into the current
// framebuffer and viewport (an empty vertex array bound for the draw).
void drawFullScreenTriangle();

}  // namespace skybake::gl
