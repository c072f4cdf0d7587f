#include "yaml_document_check.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {
namespace {

int markLine(const YAML::Mark& mark) { return mark.line >= 0 ? mark.line + 1 : 0; }

enum class YamlKind { Null, Scalar, Sequence, Map };

std::string describeKind(YamlKind kind) {
  switch (kind) {
    case YamlKind::Null:
      return "nothing";
    case YamlKind::Sequence:
      return "a list";
    case YamlKind::Map:
      return "a map";
    default:
      return "a text";
  }
}

/// A value the parser has named with `&name`: what an alias to it stands for.
struct YamlAnchor {
  std::string name;
  int line = 0;
  bool open = false;  ///< its list or map has not ended yet: an alias to it now is a cycle
  YamlKind kind = YamlKind::Null;
  std::string scalar;
  std::size_t values = 1;  ///< values it holds, itself included, aliases expanded
  std::size_t height = 1;  ///< levels of nesting, aliases expanded (a scalar: 1)
};

/// A list or map being read.
struct YamlFrame {
  YamlKind kind = YamlKind::Map;
  YAML::anchor_t anchor = YAML::NullAnchor;
  std::size_t valuesBefore = 0;  ///< the document's count before this collection began
  std::size_t height = 1;
  std::size_t index = 0;  ///< a list: the element being read
  bool atKey = true;      ///< a map: the next value is a key
  std::string key;        ///< a map: the key of the value being read
  std::unordered_map<std::string, int> keyLines;
};

class DocumentCheck : public YAML::EventHandler {
 public:
  explicit DocumentCheck(const std::string& file) : file_(file) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnAnchor(const YAML::Mark& mark, const std::string& name) override {
    pendingName_ = name;
    pendingLine_ = markLine(mark);
  }
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    leaf(YamlKind::Null, std::string(), mark, anchor);
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    leaf(YamlKind::Scalar, value, mark, anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const YamlAnchor& named = anchorAt(anchor);
    if (named.open)
      fail(placeOfNext(), markLine(mark),
           "the alias " + quotedText(named.name) + " is inside the value it names (anchor on line " +
               std::to_string(named.line) + "); a value cannot contain itself");
    count(named.values);
    complete(named.kind, named.scalar, mark, named.height);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    begin(YamlKind::Sequence, mark, anchor);
  }
  void OnSequenceEnd() override { end(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    begin(YamlKind::Map, mark, anchor);
  }
  void OnMapEnd() override { end(); }

 private:
  YamlAnchor& anchorAt(YAML::anchor_t anchor) {
    if (anchor >= anchors_.size()) anchors_.resize(anchor + 1);
    return anchors_[anchor];
  }

  YamlAnchor& define(YAML::anchor_t anchor, YamlKind kind) {
    YamlAnchor& named = anchorAt(anchor);
    named = YamlAnchor{pendingName_, pendingLine_, false, kind, {}, 1, 1};
    return named;
  }

  void leaf(YamlKind kind, const std::string& value, const YAML::Mark& mark, YAML::anchor_t anchor) {
    count(1);
    if (anchor != YAML::NullAnchor) define(anchor, kind).scalar = value;
    complete(kind, value, mark, 1);
  }

  void begin(YamlKind kind, const YAML::Mark& mark, YAML::anchor_t anchor) {
    count(1);
    if (anchor != YAML::NullAnchor) define(anchor, kind).open = true;
    YamlFrame frame;
    frame.kind = kind;
    frame.anchor = anchor;
    frame.valuesBefore = values_ - 1;
    stack_.push_back(std::move(frame));
    marks_.push_back(mark);
  }

  void end() {
    const YamlFrame frame = std::move(stack_.back());
    const YAML::Mark mark = marks_.back();
    stack_.pop_back();
    marks_.pop_back();
    if (frame.anchor != YAML::NullAnchor) {
      YamlAnchor& named = anchorAt(frame.anchor);
      named.open = false;
      named.values = values_ - frame.valuesBefore;
      named.height = frame.height;
    }
    complete(frame.kind, std::string(), mark, frame.height);
  }

  /// A value has been read whole: it is the next key or value of the collection that holds it.
  void complete(YamlKind kind, const std::string& scalar, const YAML::Mark& mark, std::size_t height) {
    if (stack_.size() + height > kMaxYamlDepth)  // at its line: its path would be thousands of steps long
      fail("", markLine(mark),
           "nested more than " + std::to_string(kMaxYamlDepth) +
               " levels deep (through aliases?), the most pmdplan reads");
    if (stack_.empty()) return;
    YamlFrame& top = stack_.back();
    top.height = std::max(top.height, height + 1);
    if (top.kind == YamlKind::Sequence) {
      ++top.index;
    } else if (!top.atKey) {
      top.atKey = true;
    } else {
      const std::string mapPath = placeOfNext();
      if (kind != YamlKind::Scalar)
        fail(mapPath, markLine(mark), "map keys must be plain names, got " + describeKind(kind));
      const int line = markLine(mark);
      if (const auto previous = top.keyLines.find(scalar); previous != top.keyLines.end())
        fail(joinFieldPath(mapPath, scalar), line,
             "given twice (first on line " + std::to_string(previous->second) + "); each key may appear once");
      top.keyLines.emplace(scalar, line);
      top.key = scalar;
      top.atKey = false;
    }
  }

  void count(std::size_t values) {
    values_ += values;
    if (values_ > kMaxYamlValues)
      throw InputError(
          file_, "document",
          "more than " + std::to_string(kMaxYamlValues) + " values (through aliases?), the most pmdplan reads");
  }

  /// The field path of the value read next (a key: the path of its map).
  std::string placeOfNext() const {
    std::string path;
    for (const YamlFrame& frame : stack_) {
      if (frame.kind == YamlKind::Sequence)
        path += "[" + std::to_string(frame.index) + "]";
      else if (!frame.atKey)
        path = joinFieldPath(path, frame.key);
    }
    return path;
  }

  [[noreturn]] void fail(const std::string& path, int line, const std::string& message) const {
    std::string field = path.empty() ? std::string("document") : path;
    if (line > 0) field += " (line " + std::to_string(line) + ")";
    throw InputError(file_, field, message);
  }

  const std::string& file_;
  std::vector<YamlFrame> stack_;
  std::vector<YAML::Mark> marks_;
  std::vector<YamlAnchor> anchors_;
  std::string pendingName_;
  int pendingLine_ = 0;
  std::size_t values_ = 0;
};

}  // namespace

void checkYamlDocument(std::string_view text, const std::string& file) {
  std::istringstream stream{std::string(text)};
  YAML::Parser parser(stream);
  DocumentCheck check(file);
  try {
    parser.HandleNextDocument(check);
  } catch (const YAML::Exception& error) {
    throw InputError(
        file, "line " + std::to_string(error.mark.line + 1) + ", column " + std::to_string(error.mark.column + 1),
        "YAML syntax error: " + error.msg);
  }
}

}  // namespace pmdplan
