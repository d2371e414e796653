#include <glcontext/context.h>

namespace glcontext {

void DebugLog::install() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(&DebugLog::callback, this);
  // Push/pop group notifications are our own markers, not news.
  glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0,
                        nullptr, GL_FALSE);
  glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_POP_GROUP, GL_DONT_CARE, 0,
                        nullptr, GL_FALSE);
}

void GLAPIENTRY DebugLog::callback(GLenum source, GLenum type, GLuint id, GLenum severity,
                                   GLsizei length, const GLchar* message, const void* user) {
  auto* log = static_cast<DebugLog*>(const_cast<void*>(user));
  std::lock_guard lock(log->mutex_);
  log->messages_.push_back(
      {source, type, severity, id,
       length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message)});
}

std::vector<DebugMessage> DebugLog::take() {
  std::lock_guard lock(mutex_);
  std::vector<DebugMessage> result;
  result.swap(messages_);
  return result;
}

size_t DebugLog::errorCount() const {
  std::lock_guard lock(mutex_);
  size_t count = 0;
  for (const DebugMessage& message : messages_) count += message.type == GL_DEBUG_TYPE_ERROR;
  return count;
}

std::string debugMessageString(const DebugMessage& message) {
  const char* kind = message.type == GL_DEBUG_TYPE_ERROR                 ? "error"
                     : message.type == GL_DEBUG_TYPE_PERFORMANCE         ? "performance"
                     : message.type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR ? "deprecated"
                     : message.type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR  ? "undefined"
                                                                         : "other";
  return std::string("GL ") + kind + " " + std::to_string(message.id) + ": " + message.text;
}

}  // namespace glcontext
