#include "core/work_instrumentation.h"

#include <array>
#include <cctype>

#include "core/work_account.h"

namespace postfx::detail {
namespace {

constexpr std::array<std::string_view, 12> kFetches = {
    "texture",       "textureLod",          "textureOffset", "textureLodOffset",
    "textureGrad",   "textureGradOffset",   "texelFetch",    "texelFetchOffset",
    "textureGather", "textureGatherOffset", "textureProj",   "imageLoad"};
constexpr std::array<std::string_view, 14> kAtomics = {"atomicAdd",
                                                       "atomicMin",
                                                       "atomicMax",
                                                       "atomicAnd",
                                                       "atomicOr",
                                                       "atomicXor",
                                                       "atomicExchange",
                                                       "atomicCompSwap",
                                                       "imageAtomicAdd",
                                                       "imageAtomicMin",
                                                       "imageAtomicMax",
                                                       "imageAtomicExchange",
                                                       "imageAtomicCompSwap",
                                                       "atomicCounterIncrement"};

bool identifierChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

template <std::size_t N>
bool among(std::string_view token, const std::array<std::string_view, N>& names) {
  for (std::string_view name : names)
    if (token == name) return true;
  return false;
}

// The end of a comment starting at i, or i when none starts there.
std::size_t commentEnd(std::string_view s, std::size_t i) {
  if (i + 1 >= s.size() || s[i] != '/') return i;
  if (s[i + 1] == '/') {
    const std::size_t end = s.find('\n', i);
    return end == std::string_view::npos ? s.size() : end;
  }
  if (s[i + 1] == '*') {
    const std::size_t end = s.find("*/", i + 2);
    return end == std::string_view::npos ? s.size() : end + 2;
  }
  return i;
}

std::size_t skipSpace(std::string_view s, std::size_t i) {
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])) != 0) ++i;
  return i;
}

// The ')' closing the '(' at `open`, or npos.
std::size_t closingParen(std::string_view s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    const std::size_t end = commentEnd(s, i);
    if (end != i) {
      i = end - 1;
      continue;
    }
    if (s[i] == '(') ++depth;
    if (s[i] == ')' && --depth == 0) return i;
  }
  return std::string_view::npos;
}

std::string rewrite(std::string_view s) {
  std::string out;
  out.reserve(s.size() + s.size() / 4);
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t end = commentEnd(s, i);
    if (end != i) {
      out.append(s.substr(i, end - i));
      i = end;
      continue;
    }
    const bool starts = (std::isalpha(static_cast<unsigned char>(s[i])) != 0 || s[i] == '_') &&
                        (i == 0 || !identifierChar(s[i - 1]));
    if (!starts) {
      out += s[i++];
      continue;
    }
    std::size_t j = i;
    while (j < s.size() && identifierChar(s[j])) ++j;
    const std::string_view token = s.substr(i, j - i);
    const std::size_t next = skipSpace(s, j);
    const bool fetch = among(token, kFetches), atomic = among(token, kAtomics);
    if ((fetch || atomic) && next < s.size() && s[next] == '(') {
      const std::size_t close = closingParen(s, next);
      if (close != std::string_view::npos) {
        out += fetch ? "(postfxFetches += 1u, " : "(postfxAtomics += 1u, ";
        out.append(token);
        out += '(';
        out += rewrite(s.substr(next + 1, close - next - 1));
        out += "))";
        i = close + 1;
        continue;
      }
    }
    if (token == "discard" && next < s.size() && s[next] == ';') {
      out += "{ postfxFlushWork(); discard; }";
      i = next + 1;
      continue;
    }
    if (token == "void") {
      const std::size_t name = next;
      if (s.substr(name, 4) == "main" && (name + 4 >= s.size() || !identifierChar(s[name + 4]))) {
        out += "void postfxCountedMain";
        i = name + 4;
        continue;
      }
    }
    out.append(token);
    i = j;
  }
  return out;
}

int stageIndex(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return kWorkVertexStage;
    case GL_FRAGMENT_SHADER:
      return kWorkFragmentStage;
    case GL_COMPUTE_SHADER:
      return kWorkComputeStage;
    default:
      return -1;
  }
}

}  // namespace

void countWork(GLenum stage, std::string& source) {
  const int index = stageIndex(stage);
  if (index < 0) return;
  // glkit's preprocess puts "#line 2" before the body: the counters go just ahead of it, so the
  // body keeps its line numbers (after #version and the defines, before any use).
  std::size_t body = source.find("\n#line 2\n");
  if (body == std::string::npos) body = source.find('\n', source.find("#version"));
  if (body == std::string::npos) return;
  ++body;
  auto counter = [index](int k) { return "postfxWork[" + std::to_string(3 * index + k) + "]"; };
  const std::string prelude = "layout(std430, binding = " + std::to_string(kWorkCounterBinding) +
                              ") buffer PostfxWorkCounters { uint postfxWork[" +
                              std::to_string(kWorkCounterCount) +
                              "]; };\n"
                              "uint postfxFetches = 0u;\n"
                              "uint postfxAtomics = 0u;\n"
                              "void postfxFlushWork() {\n"
                              "  atomicAdd(" +
                              counter(kWorkInvocations) +
                              ", 1u);\n"
                              "  if (postfxFetches != 0u) atomicAdd(" +
                              counter(kWorkFetches) +
                              ", postfxFetches);\n"
                              "  if (postfxAtomics != 0u) atomicAdd(" +
                              counter(kWorkAtomics) +
                              ", postfxAtomics);\n"
                              "}\n";
  source = source.substr(0, body) + prelude + rewrite(std::string_view(source).substr(body)) +
           "\nvoid main() {\n  postfxCountedMain();\n  postfxFlushWork();\n}\n";
}

}  // namespace postfx::detail
