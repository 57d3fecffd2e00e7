#pragma once
// The one place that talks to OpenGL (3.3 core, loaded through libepoxy). Small
// move-only RAII wrappers for the objects the renderer needs, and the few state and
// draw calls it makes; nothing outside ui/gl/ calls gl* directly.
//
// Errors (a shader that does not compile, a framebuffer that is incomplete) throw
// GlError with the shader file's name and the driver's log.

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace ew::gl {

class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// [SECTION] Handle: one GL name plus its deleter, move-only.
template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  ~Handle() { reset(); }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

void deleteBuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteRenderbuffer(GLuint id);

// [SECTION] Buffers and vertex arrays

// A GL_ARRAY_BUFFER whose contents are replaced as a whole (instance data per frame).
class Buffer {
 public:
  Buffer();
  // Replaces the contents (grows the storage when needed, orphans it otherwise).
  void upload(const void* data, std::size_t bytes);
  template <class T>
  void upload(std::span<const T> items) {
    upload(items.data(), items.size_bytes());
  }
  GLuint id() const { return handle_.id(); }

 private:
  Handle<deleteBuffer> handle_;
  std::size_t capacity_ = 0;
};

// One float vector attribute of an interleaved per-instance record.
struct InstanceAttribute {
  GLuint location = 0;
  GLint components = 4;       // 1…4 floats
  std::size_t offsetBytes = 0;
};

class VertexArray {
 public:
  VertexArray();
  // Declares per-instance float attributes (divisor 1) read from `buffer`.
  void setInstanceLayout(const Buffer& buffer, std::size_t strideBytes,
                         std::span<const InstanceAttribute> attributes);
  void bind() const;
  GLuint id() const { return handle_.id(); }

 private:
  Handle<deleteVertexArray> handle_;
};

// [SECTION] Programs

class Program {
 public:
  Program() = default;
  // Compiles and links the two shader files; throws GlError naming the file and
  // quoting the driver's log when either step fails.
  static Program fromFiles(const std::filesystem::path& vertexFile,
                           const std::filesystem::path& fragmentFile);

  void use() const;
  void set(const char* name, float v);
  void set(const char* name, int v);
  void set(const char* name, const glm::vec2& v);
  void set(const char* name, const glm::vec3& v);
  void set(const char* name, const glm::vec4& v);
  void set(const char* name, const glm::mat4& v);
  GLuint id() const { return handle_.id(); }

 private:
  GLint location(const char* name);
  Handle<deleteProgram> handle_;
  std::unordered_map<std::string, GLint> locations_;
};

// [SECTION] Textures and render targets

class Texture2D {
 public:
  Texture2D() = default;
  // RGBA8, linear filtering, clamped; contents undefined.
  void allocate(int width, int height);
  // Replaces the contents with 8-bit BGR rows (`strideBytes` apart, top row first), the
  // storage reallocated when the size changes.
  void uploadBgr(int width, int height, const unsigned char* bgr, std::size_t strideBytes);
  void bind(int unit) const;
  GLuint id() const { return handle_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  // For ImGui::Image.
  void* imguiId() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(id())); }

 private:
  Handle<deleteTexture> handle_;
  int width_ = 0, height_ = 0;
};

// An offscreen target: a multisampled colour (+ depth) framebuffer that is resolved into
// a plain texture. Resized on demand.
class RenderTarget {
 public:
  RenderTarget() = default;
  // (Re)allocates when the size, sample count or depth changes. samples is clamped to
  // what the driver supports (1 = no multisampling).
  void ensure(int width, int height, int samples, bool depth = true);
  // Binds the multisampled framebuffer and sets the viewport to the whole target; counts
  // as a new image (generation()).
  void begin();
  // Resolves into the texture and binds the default framebuffer again.
  void end() const;
  const Texture2D& texture() const { return resolved_; }
  // RGB rows of the resolved image (after end()), bottom row first.
  std::vector<unsigned char> readPixelsRgb() const;
  // Copies the resolved image 1:1 into the default framebuffer with its lower-left corner
  // at (x, y) (framebuffer pixels, origin bottom-left).
  void blitToDefault(int x, int y) const;
  // The same into another (single-sampled) target's image.
  void blitInto(const RenderTarget& target, int x, int y) const;
  // How many times it was drawn into (begin()): tells a changed image from the same one.
  std::uint64_t generation() const { return generation_; }
  int width() const { return width_; }
  int height() const { return height_; }
  bool valid() const { return width_ > 0 && height_ > 0; }

 private:
  void blitTo(GLuint drawFramebuffer, int x, int y) const;

  Handle<deleteFramebuffer> msaaFbo_, resolveFbo_;
  Handle<deleteRenderbuffer> colour_, depthBuffer_;
  Texture2D resolved_;
  int width_ = 0, height_ = 0, samples_ = 0;
  bool hasDepth_ = false;
  std::uint64_t generation_ = 0;
};

// [SECTION] State and draw calls

enum class Blend { None, Alpha, Additive };

struct DrawState {
  bool depthTest = true;
  bool depthWrite = true;
  Blend blend = Blend::None;
  bool alphaToCoverage = false;
  bool colourWrite = true;
  bool depthEqual = false;  // GL_EQUAL instead of GL_LEQUAL (second pass over a depth pre-pass)
};

void apply(const DrawState& state);
void clear(const glm::vec4& colour);
// The colour buffer only (the default framebuffer has no depth).
void clearColour(const glm::vec4& colour);
// Fills a rectangle of the bound framebuffer (pixels, origin bottom-left) with a colour:
// a scissored clear, no shading.
void fillRect(int x, int y, int width, int height, const glm::vec4& colour);
// Instanced 4-vertex triangle strip (the quad corners come from gl_VertexID).
void drawQuads(const VertexArray& vao, int instances);
// A single quad (or full-screen triangle strip) with no attributes.
void drawQuad(const VertexArray& vao);

// Waits until the GL has finished (profiling only).
void finish();

// The default framebuffer.
void bindDefaultFramebuffer(int width, int height);
// RGB rows of the currently bound read framebuffer, bottom row first.
std::vector<unsigned char> readPixelsRgb(int width, int height);

// "OpenGL 3.3 (Mesa llvmpipe …)" for the log.
std::string describeContext();
int maxSamples();

}  // namespace ew::gl
