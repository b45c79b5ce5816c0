// Reads shaders/shared/gpu_records.def (its first lines say the format) and lays every
// record out by std430, refusing one whose C++ layout would differ.
#include <map>
#include <sstream>
#include <stdexcept>

#include "gpu_records.h"

namespace vkpt::records {
namespace {

// Size and alignment of a type in std430 (GLSL) and in C++ (glm: every type 4-aligned).
struct TypeLayout {
  unsigned size, align430;
};
const std::map<std::string, TypeLayout> kTypes = {
    {"uint", {4, 4}}, {"float", {4, 4}}, {"vec2", {8, 8}}, {"vec3", {12, 16}}, {"uvec4", {16, 16}}};

unsigned RoundUp(unsigned x, unsigned a) { return (x + a - 1) / a * a; }

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// "code // comment" → (words of code, comment).
std::vector<std::string> Words(const std::string& line, std::string* comment) {
  const size_t slash = line.find("//");
  if (comment) *comment = slash == std::string::npos ? "" : Trim(line.substr(slash + 2));
  std::istringstream in(line.substr(0, slash));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

class Parser {
 public:
  explicit Parser(const std::string& file) : file_(file) {}

  Description Run(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      ++lineNo_;
      const std::string t = Trim(line);
      if (t.empty() || t[0] == '#') continue;
      if (record_) Body(t);
      else if (t.rfind("record ", 0) == 0) Header(Words(t, nullptr));
      else if (t.rfind("slot ", 0) == 0) AddSlot(t);
      else Fail("expected `record` or `slot`, got: " + t);
    }
    if (record_) Fail("record " + record_->name + " has no `end`");
    return d_;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw std::runtime_error(file_ + ":" + std::to_string(lineNo_) + ": " + what);
  }

  void Header(const std::vector<std::string>& w) {
    if (w.size() < 2) Fail("a record needs a name");
    Record r;
    r.name = r.shortName = w[1];
    for (size_t i = 2; i < w.size(); ++i) {
      auto next = [&]() -> const std::string& {
        if (++i >= w.size()) Fail("`" + w[i - 1] + "` needs a value");
        return w[i];
      };
      if (w[i] == "as") r.shortName = next();
      else if (w[i] == "texels") r.sampler = next();
      else if (w[i] == "base") r.base = next();
      else if (w[i] == "split") {
        r.high = next();
        r.flag = next();
        r.splitVar = next();
      } else Fail("unknown record option `" + w[i] + "`");
    }
    d_.records.push_back(r);
    record_ = &d_.records.back();
    pendingCondition_.clear();
  }

  void Body(const std::string& t) {
    Record& r = *record_;
    if (t == "end") return End();
    if (t.rfind("//", 0) == 0) {
      if (FieldCount() == 0) r.doc.push_back(t);
      else r.items.push_back({false, {}, t});
      return;
    }
    std::string comment;
    std::vector<std::string> w = Words(t, &comment);
    if (w[0] == "texel") {
      if (w.size() < 3 || w[1] != "if") Fail("expected `texel if <condition>`");
      pendingCondition_ = Trim(t.substr(t.find("if") + 2));
      return;
    }
    if (!kTypes.count(w[0])) Fail("unknown type `" + w[0] + "` (uint, float, vec2, vec3, uvec4)");
    if (w.size() < 2 || (w.size() == 3 && w[2] != "@fetch") || w.size() > 3) Fail("expected `<type> <name> [@fetch]`");
    Field f{w[0], w[1], comment, w.size() == 3, 0};
    Place(f);
    r.items.push_back({true, f, ""});
  }

  size_t FieldCount() const {
    size_t n = 0;
    for (const Item& i : record_->items) n += i.isField;
    return n;
  }

  // Lays f out after the fields so far: its std430 offset, which must also be C++'s.
  void Place(Field& f) {
    Record& r = *record_;
    const TypeLayout t = kTypes.at(f.type);
    f.offset = RoundUp(cppEnd_, t.align430);
    if (f.offset != cppEnd_)
      Fail(f.name + ": std430 puts this " + f.type + " at byte " + std::to_string(f.offset) + ", C++ at " +
           std::to_string(cppEnd_) + "; reorder the fields or add a uint pad field");
    cppEnd_ = f.offset + t.size;
    maxAlign_ = std::max(maxAlign_, t.align430);
    const unsigned texel = f.offset / 16;
    if (r.texelCondition.size() <= texel) r.texelCondition.resize(texel + 1);
    if (!pendingCondition_.empty()) {
      if (f.offset % 16 != 0) Fail("`texel if` must come before a field that starts a texel");
      r.texelCondition[texel] = pendingCondition_;
      pendingCondition_.clear();
    }
    if (f.fetch && !r.splitVar.empty()) Fail("@fetch is for records without a split");
  }

  void End() {
    Record& r = *record_;
    if (FieldCount() == 0) Fail("record " + r.name + " has no fields");
    r.size = RoundUp(cppEnd_, maxAlign_);
    if (r.size != cppEnd_)
      Fail("std430 rounds " + r.name + " up to " + std::to_string(r.size) + " bytes, C++ to " +
           std::to_string(cppEnd_) + "; add uint pad fields");
    if (!r.sampler.empty() && r.size % 16 != 0) Fail(r.name + " is read from texels: make it a multiple of 16 bytes");
    if (!r.splitVar.empty() && r.Texels() != 3) Fail(r.name + ": a split record must be three texels");
    r.texelCondition.resize(r.Texels());
    record_ = nullptr;
    cppEnd_ = maxAlign_ = 0;
  }

  void AddSlot(const std::string& t) {
    std::string comment;
    const std::vector<std::string> w = Words(t, &comment);
    if (w.size() != 4 || (w[2] != "colour" && w[2] != "data")) Fail("expected `slot <name> <colour|data> <path>`");
    d_.slots.push_back({w[1], w[2] == "colour", w[3], comment});
  }

  std::string file_;
  int lineNo_ = 0;
  Description d_;
  Record* record_ = nullptr;  // the record being read (no other is added meanwhile)
  unsigned cppEnd_ = 0, maxAlign_ = 0;
  std::string pendingCondition_;
};

}  // namespace

Description Parse(const std::string& text, const std::string& file) { return Parser(file).Run(text); }

std::string Capitalized(const std::string& s) {
  std::string c = s;
  if (!c.empty() && c[0] >= 'a' && c[0] <= 'z') c[0] = char(c[0] - 'a' + 'A');
  return c;
}

}  // namespace vkpt::records
