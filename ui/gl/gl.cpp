#include "ui/gl/gl.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

namespace ew::gl {

// [SECTION] Deleters

void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteProgram(GLuint id) { glDeleteProgram(id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }

// [SECTION] Buffers and vertex arrays

Buffer::Buffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  handle_ = Handle<deleteBuffer>(id);
}

void Buffer::upload(const void* data, std::size_t bytes) {
  glBindBuffer(GL_ARRAY_BUFFER, handle_.id());
  if (bytes > capacity_) {
    capacity_ = std::max<std::size_t>(bytes, 2 * capacity_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
  } else {
    // Orphan the old storage so the driver need not wait for the previous frame.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
  }
  if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

VertexArray::VertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  handle_ = Handle<deleteVertexArray>(id);
}

void VertexArray::setInstanceLayout(const Buffer& buffer, std::size_t strideBytes,
                                    std::span<const InstanceAttribute> attributes) {
  glBindVertexArray(handle_.id());
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  for (const auto& a : attributes) {
    glEnableVertexAttribArray(a.location);
    glVertexAttribPointer(a.location, a.components, GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(strideBytes),
                          reinterpret_cast<const void*>(a.offsetBytes));
    glVertexAttribDivisor(a.location, 1);
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void VertexArray::bind() const { glBindVertexArray(handle_.id()); }

// [SECTION] Programs

namespace {

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GlError(file.string() + ": cannot read shader file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

GLuint compile(GLenum stage, const std::filesystem::path& file) {
  const std::string source = readText(file);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw GlError(file.string() + ": shader does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

Program Program::fromFiles(const std::filesystem::path& vertexFile,
                           const std::filesystem::path& fragmentFile) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexFile);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentFile);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  Program program;
  program.handle_ = Handle<deleteProgram>(glCreateProgram());
  const GLuint id = program.handle_.id();
  glAttachShader(id, vs);
  glAttachShader(id, fs);
  glLinkProgram(id);
  glDetachShader(id, vs);
  glDetachShader(id, fs);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(id, length, nullptr, log.data());
    throw GlError(vertexFile.string() + " + " + fragmentFile.filename().string() +
                  ": program does not link:\n" + log);
  }
  return program;
}

void Program::use() const { glUseProgram(handle_.id()); }

GLint Program::location(const char* name) {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(handle_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const char* name, float v) { glUniform1f(location(name), v); }
void Program::set(const char* name, int v) { glUniform1i(location(name), v); }
void Program::set(const char* name, const glm::vec2& v) {
  glUniform2fv(location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) {
  glUniform3fv(location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec4& v) {
  glUniform4fv(location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat4& v) {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(v));
}

// [SECTION] Textures and render targets

void Texture2D::uploadBgr(int width, int height, const unsigned char* bgr, std::size_t strideBytes) {
  if (!handle_ || width != width_ || height != height_) allocate(width, height);
  glBindTexture(GL_TEXTURE_2D, handle_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(strideBytes / 3));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_BGR, GL_UNSIGNED_BYTE, bgr);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void Texture2D::bind(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, handle_.id());
}

void Texture2D::allocate(int width, int height) {
  width_ = width;
  height_ = height;
  if (!handle_) {
    GLuint id = 0;
    glGenTextures(1, &id);
    handle_ = Handle<deleteTexture>(id);
  }
  glBindTexture(GL_TEXTURE_2D, handle_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
}

int maxSamples() {
  GLint samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  return std::max(1, static_cast<int>(samples));
}

void RenderTarget::ensure(int width, int height, int samples, bool depth) {
  width = std::max(width, 1);
  height = std::max(height, 1);
  samples = std::clamp(samples, 1, maxSamples());
  if (width == width_ && height == height_ && samples == samples_ && depth == hasDepth_) return;
  width_ = width;
  height_ = height;
  samples_ = samples;
  hasDepth_ = depth;

  auto makeFbo = [] {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return Handle<deleteFramebuffer>(id);
  };
  auto makeRbo = [] {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    return Handle<deleteRenderbuffer>(id);
  };
  if (!msaaFbo_) msaaFbo_ = makeFbo();
  if (!resolveFbo_) resolveFbo_ = makeFbo();
  colour_ = makeRbo();
  depthBuffer_ = depth ? makeRbo() : Handle<deleteRenderbuffer>();

  resolved_.allocate(width, height);
  if (depth) {
    glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer_.id());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, GL_DEPTH_COMPONENT32F,
                                     width, height);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo_.id());
  if (samples > 1) {
    glBindRenderbuffer(GL_RENDERBUFFER, colour_.id());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
  } else {
    // Single-sampled: draw straight into the texture, no resolve copy.
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolved_.id(), 0);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer_.id());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = height_ = 0;
    throw GlError("offscreen framebuffer (" + std::to_string(samples) + " samples) incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolved_.id(), 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = height_ = 0;
    throw GlError("resolve framebuffer incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::begin() {
  ++generation_;
  glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTarget::end() const {
  if (samples_ <= 1) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msaaFbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_.id());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<unsigned char> RenderTarget::readPixelsRgb() const {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolveFbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return pixels;
}

void RenderTarget::blitTo(GLuint drawFramebuffer, int x, int y) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolveFbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, drawFramebuffer);
  glBlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::blitToDefault(int x, int y) const { blitTo(0, x, y); }

void RenderTarget::blitInto(const RenderTarget& target, int x, int y) const {
  blitTo(target.resolveFbo_.id(), x, y);
}

// [SECTION] State and draw calls

void apply(const DrawState& state) {
  if (state.depthTest) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(state.depthEqual ? GL_EQUAL : GL_LEQUAL);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(state.depthWrite ? GL_TRUE : GL_FALSE);
  switch (state.blend) {
    case Blend::None:
      glDisable(GL_BLEND);
      break;
    case Blend::Alpha:
      glEnable(GL_BLEND);
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
      break;
    case Blend::Additive:
      glEnable(GL_BLEND);
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ONE, GL_ONE);
      break;
  }
  if (state.alphaToCoverage) {
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  } else {
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
  const GLboolean c = state.colourWrite ? GL_TRUE : GL_FALSE;
  glColorMask(c, c, c, c);
  glDisable(GL_CULL_FACE);
  glEnable(GL_MULTISAMPLE);
}

void clear(const glm::vec4& colour) {
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void clearColour(const glm::vec4& colour) {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glClear(GL_COLOR_BUFFER_BIT);
}

void fillRect(int x, int y, int width, int height, const glm::vec4& colour) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, std::max(width, 0), std::max(height, 0));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

void drawQuads(const VertexArray& vao, int instances) {
  if (instances <= 0) return;
  vao.bind();
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances);
  glBindVertexArray(0);
}

void drawQuad(const VertexArray& vao) {
  vao.bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
}

void finish() { glFinish(); }

void bindDefaultFramebuffer(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

std::vector<unsigned char> readPixelsRgb(int width, int height) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

std::string describeContext() {
  auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return "OpenGL " + str(GL_VERSION) + " (" + str(GL_RENDERER) + ")";
}

}  // namespace ew::gl
