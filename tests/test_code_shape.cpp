// The code stays in small pieces: no source file of the product (host/, include/,
// shaders/, bench/, scripts/) over 300 lines, no function over 60 there or in tests/. Generated files live
// in the build tree and are not walked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <initializer_list>
#include <regex>
#include <string>
#include <vector>

#include "test_util.h"

namespace vkpt::internal {
namespace {

constexpr size_t kMaxFileLines = 300, kMaxFunctionLines = 60;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

// A line's code: string and character literals emptied, a // comment dropped.
std::string Code(const std::string& line) {
  static const std::regex literal(R"("(\\.|[^"\\])*"|'(\\.|[^'\\])*')");
  std::string code = std::regex_replace(line, literal, "\"\"");
  const size_t comment = code.find("//");
  return comment == std::string::npos ? code : code.substr(0, comment);
}

// The text with each raw string literal, R"d(…)d", emptied to R"" plus the line breaks it
// held (so that lines keep their numbers): its braces and quotes are not code.
std::string WithoutRawStrings(const std::string& text) {
  std::string out;
  size_t at = 0;
  for (size_t raw = text.find("R\""); raw != std::string::npos; raw = text.find("R\"", raw + 2)) {
    if (raw < at || (raw > 0 && (std::isalnum(static_cast<unsigned char>(text[raw - 1])) || text[raw - 1] == '_')))
      continue;  // inside the last one, or the end of a name or of a plain string ("SCALAR")
    const size_t open = text.find('(', raw);
    if (open == std::string::npos) break;
    // Appended piece by piece: GCC 12 warns falsely on ")" + std::string (bug 105651).
    std::string close = ")";
    close += text.substr(raw + 2, open - raw - 2);
    close += '"';
    const size_t end = text.find(close, open);
    if (end == std::string::npos) break;
    out += text.substr(at, raw - at) + "R\"\"";
    out += std::string(std::count(text.begin() + open, text.begin() + end, '\n'), '\n');
    at = end + close.size();
  }
  return out + text.substr(at);
}

// "name (line N): M lines" for each function of `text` (C++ or GLSL) longer than the
// limit: a definition starts at a line, at most two spaces in, that names a function
// (type, name, open parenthesis) and is no statement, and ends where its braces close.
std::vector<std::string> LongFunctions(const std::string& source) {
  const std::string text = WithoutRawStrings(source);
  static const std::regex start(R"(^(  )?[A-Za-z_][\w:<>,\s\*&\[\]]*\s[\*&]?[\w:~]+(<[^>]*>)?\s*\()");
  static const std::regex statement(R"(^\s*(return|else|if|for|while|switch|case|using|typedef|static_assert|#))");
  const std::vector<std::string> lines = Lines(text);
  std::vector<std::string> found;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string first = Code(lines[i]);
    if (!std::regex_search(first, start) || std::regex_search(first, statement)) continue;
    int depth = 0;
    bool body = false;
    size_t j = i;
    for (; j < lines.size(); ++j) {
      const std::string code = Code(lines[j]);
      const size_t last = code.find_last_not_of(" \t");
      if (!body && last != std::string::npos && code[last] == ';') break;  // a declaration
      for (char c : code) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
      body = body || code.find('{') != std::string::npos;
      if (body && depth <= 0) break;
    }
    if (!body || j == lines.size()) continue;
    if (j - i + 1 > kMaxFunctionLines)
      found.push_back(lines[i].substr(0, 60) + " (line " + std::to_string(i + 1) + "): " + std::to_string(j - i + 1) +
                      " lines");
    i = j;
  }
  return found;
}

std::vector<std::filesystem::path> Sources(std::initializer_list<const char*> dirs) {
  static const std::regex source(R"(.*\.(h|cpp|glsl|comp)$)");
  std::vector<std::filesystem::path> files;
  for (const char* dir : dirs)
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::SourcePath(dir)))
      if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), source))
        files.push_back(entry.path());
  return files;
}

TEST(CodeShape, NoFileOver300LinesNoFunctionOver60) {
  const std::vector<std::filesystem::path> files = Sources({"host", "include", "shaders", "bench", "scripts"});
  EXPECT_GE(files.size(), 250u);
  for (const std::filesystem::path& file : files) {
    const std::string text = test::ReadFile(file.string());
    EXPECT_LE(Lines(text).size(), kMaxFileLines) << file.string();
    for (const std::string& f : LongFunctions(text)) ADD_FAILURE() << file.string() << ": " << f;
  }
}

// Tests read as their steps too: no function over 60 lines (a test file may be long).
TEST(CodeShape, NoTestFunctionOver60) {
  const std::vector<std::filesystem::path> files = Sources({"tests"});
  EXPECT_GE(files.size(), 100u);
  for (const std::filesystem::path& file : files)
    for (const std::string& f : LongFunctions(test::ReadFile(file.string())))
      ADD_FAILURE() << file.string() << ": " << f;
}

// The scanner finds what it must: a 61-line function in C++ or GLSL, not a 60-line one,
// nor a declaration, a statement or braces inside strings and comments.
std::string Function(const std::string& head, size_t lines) {
  std::string text = head + " {\n";
  for (size_t k = 2; k < lines; ++k) text += "  x += \"}\";  // }\n";
  return text + "}\n";
}

TEST(CodeShape, TheScannerCountsFunctionsAsWritten) {
  EXPECT_EQ(LongFunctions(Function("int Sum(const std::vector<int>& v)", 60)).size(), 0u);
  EXPECT_EQ(LongFunctions(Function("int Sum(const std::vector<int>& v)", 61)).size(), 1u);
  EXPECT_EQ(LongFunctions(Function("vec3 Shade(vec3 p,\n               vec3 n)", 62)).size(), 1u);
  EXPECT_EQ(LongFunctions(Function("  bool Member() const", 61)).size(), 1u);
  EXPECT_EQ(LongFunctions("int Declared(int a);\n" + Function("int Short(int a)", 5)).size(), 0u);
  EXPECT_EQ(LongFunctions("  return Call(a) {\n" + std::string(70, '\n') + "}\n").size(), 0u);
  EXPECT_EQ(
      LongFunctions(Function("int Json()", 5) + "  s = R\"({\"a\":{)\";\n" + Function("int Short(int a)", 5)).size(),
      0u);
  EXPECT_EQ(LongFunctions("int Json() {\n  s = R\"x(}\n" + std::string(70, '\n') + "{)x\";\n}\n").size(), 1u);
}

}  // namespace
}  // namespace vkpt::internal
