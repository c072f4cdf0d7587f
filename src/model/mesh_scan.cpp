#include "mesh_scan.hpp"

#include <tinyxml2.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan::mesh_scan {
namespace {

constexpr std::size_t kMaxCorners = 3 * MeshLimits::kMaxTriangles;

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

std::size_t countTokens(std::string_view text) {
  std::size_t count = 0;
  bool inToken = false;
  for (const char c : text) {
    if (isSpace(c)) {
      inToken = false;
    } else if (!inToken) {
      inToken = true;
      ++count;
    }
  }
  return count;
}

[[noreturn]] void tooManyCorners(const std::string& file, const std::string& field) {
  throw InputError(file, field,
                   "more than " + std::to_string(kMaxCorners) + " face corners, more than the " +
                       std::to_string(MeshLimits::kMaxTriangles) + " triangles a mesh may have");
}

[[noreturn]] void polygonTooLarge(const std::string& file, const std::string& field, std::size_t corners) {
  throw InputError(file, field,
                   "a polygon of " + std::to_string(corners) + " corners; at most " +
                       std::to_string(MeshLimits::kMaxPolygonCorners) + " are read");
}

/// The COLLADA primitives whose <p> lists index vertices.
bool isPrimitive(const char* name) {
  static const std::set<std::string> kPrimitives{"triangles", "polylist", "polygons",  "tristrips",
                                                 "trifans",   "lines",    "linestrips"};
  return kPrimitives.count(name) > 0;
}

/// Indices per corner of a primitive: one more than its inputs' largest offset.
std::size_t indicesPerCorner(const tinyxml2::XMLElement& primitive) {
  unsigned largest = 0;
  for (const auto* input = primitive.FirstChildElement("input"); input; input = input->NextSiblingElement("input"))
    largest = std::max(largest, input->UnsignedAttribute("offset", 0));
  return static_cast<std::size_t>(largest) + 1;
}

std::string line(const tinyxml2::XMLElement& e) { return "line " + std::to_string(e.GetLineNum()); }

/// The <node> elements and the nodes each one contains or instances.
struct NodeGraph {
  std::vector<const tinyxml2::XMLElement*> nodes;
  std::vector<std::vector<std::size_t>> edges;
};

NodeGraph nodeGraph(const std::vector<const tinyxml2::XMLElement*>& nodes) {
  NodeGraph graph{nodes, std::vector<std::vector<std::size_t>>(nodes.size())};
  std::map<const tinyxml2::XMLElement*, std::size_t> index;
  std::map<std::string, std::size_t> byId;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    index.emplace(nodes[i], i);
    if (const char* id = nodes[i]->Attribute("id")) byId.emplace(id, i);
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (const auto* child = nodes[i]->FirstChildElement(); child; child = child->NextSiblingElement()) {
      if (std::strcmp(child->Name(), "node") == 0) {
        graph.edges[i].push_back(index.at(child));
      } else if (std::strcmp(child->Name(), "instance_node") == 0) {
        const char* url = child->Attribute("url");
        if (!url || url[0] != '#') continue;  // assimp resolves only local references
        if (const auto target = byId.find(url + 1); target != byId.end()) graph.edges[i].push_back(target->second);
      }
    }
  return graph;
}

/// Depth-first over the graph without recursion: refuses a cycle, and bounds each node's nesting
/// depth and expanded size.
void checkNodeGraph(const NodeGraph& graph, const std::string& file) {
  enum class State { Unvisited, Open, Done };
  const std::size_t n = graph.nodes.size();
  std::vector<State> state(n, State::Unvisited);
  std::vector<std::size_t> depth(n, 1), expanded(n, 1);
  for (std::size_t root = 0; root < n; ++root) {
    if (state[root] != State::Unvisited) continue;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{root, 0}};  // node, next edge
    state[root] = State::Open;
    while (!stack.empty()) {
      auto& [node, next] = stack.back();
      if (next < graph.edges[node].size()) {
        const std::size_t child = graph.edges[node][next++];
        if (state[child] == State::Open)
          throw InputError(
              file,
              "node " + quotedText(graph.nodes[child]->Attribute("id") ? graph.nodes[child]->Attribute("id") : "") +
                  " (" + line(*graph.nodes[child]) + ")",
              "its nodes instance each other in a cycle (<instance_node>); expected a tree of nodes");
        if (state[child] == State::Unvisited) {
          state[child] = State::Open;
          stack.emplace_back(child, 0);
        }
        continue;
      }
      for (const std::size_t child : graph.edges[node]) {
        depth[node] = std::max(depth[node], depth[child] + 1);
        expanded[node] = std::min(expanded[node] + expanded[child], MeshLimits::kMaxColladaNodeInstances + 1);
      }
      const std::string field = "node (" + line(*graph.nodes[node]) + ")";
      if (depth[node] > MeshLimits::kMaxColladaNodeDepth)
        throw InputError(file, field,
                         "nodes nested more than " + std::to_string(MeshLimits::kMaxColladaNodeDepth) +
                             " deep (through children and <instance_node>)");
      if (expanded[node] > MeshLimits::kMaxColladaNodeInstances)
        throw InputError(file, field,
                         "more than " + std::to_string(MeshLimits::kMaxColladaNodeInstances) +
                             " nodes once its <instance_node> elements are expanded");
      state[node] = State::Done;
      stack.pop_back();
    }
  }
}

}  // namespace

void checkObj(std::string_view bytes, const std::string& file) {
  std::size_t corners = 0, lineNumber = 0, start = 0;
  while (start < bytes.size()) {
    // One logical line: a backslash at the end of a physical line continues it.
    std::size_t end = start, firstLine = lineNumber + 1;
    for (;;) {
      end = bytes.find('\n', end);
      ++lineNumber;
      if (end == std::string_view::npos) {
        end = bytes.size();
        break;
      }
      std::size_t last = end;
      while (last > start && (bytes[last - 1] == '\r')) --last;
      if (last > start && bytes[last - 1] == '\\') {
        ++end;
        continue;
      }
      break;
    }
    std::string_view text = bytes.substr(start, end - start);
    start = end + 1;
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    if (text.size() < 2 || (text[0] != 'f' && text[0] != 'l' && text[0] != 'p') || !isSpace(text[1])) continue;
    const std::size_t count = countTokens(text.substr(1));
    if (text[0] == 'f' && count > MeshLimits::kMaxPolygonCorners)
      polygonTooLarge(file, "line " + std::to_string(firstLine), count);
    corners += count;
    if (corners > kMaxCorners) tooManyCorners(file, "line " + std::to_string(firstLine));
  }
}

void checkStl(std::string_view bytes, const std::string& file) {
  if (bytes.size() < 84) return;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof count);  // little-endian, as on every platform pmdplan builds for
  if (84 + 50 * static_cast<std::uint64_t>(count) == bytes.size() && count > MeshLimits::kMaxTriangles)
    throw InputError(file, "triangle count",
                     "a binary STL of " + std::to_string(count) + " triangles; a mesh may have at most " +
                         std::to_string(MeshLimits::kMaxTriangles));
}

void checkCollada(std::string_view bytes, const std::string& file) {
  tinyxml2::XMLDocument document;
  if (document.Parse(bytes.data(), bytes.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(document.ErrorLineNum()),
                     std::string("malformed XML: ") + document.ErrorName());
  std::vector<const tinyxml2::XMLElement*> nodes;
  std::size_t corners = 0;
  std::vector<const tinyxml2::XMLElement*> pending;
  if (document.RootElement()) pending.push_back(document.RootElement());
  while (!pending.empty()) {
    const tinyxml2::XMLElement* element = pending.back();
    pending.pop_back();
    const char* name = element->Name();
    if (std::strcmp(name, "node") == 0) nodes.push_back(element);
    if (std::strcmp(name, "p") == 0 || std::strcmp(name, "vcount") == 0) {
      const auto* parent = element->Parent() ? element->Parent()->ToElement() : nullptr;
      if (parent && std::strcmp(parent->Name(), "ph") == 0)
        parent = parent->Parent() ? parent->Parent()->ToElement() : nullptr;
      if (parent && isPrimitive(parent->Name())) {
        const char* text = element->GetText();
        const std::string_view values = text ? text : "";
        if (std::strcmp(name, "vcount") == 0) {
          std::size_t at = 0;
          while (at < values.size()) {
            while (at < values.size() && isSpace(values[at])) ++at;
            std::size_t value = 0;
            while (at < values.size() && !isSpace(values[at])) {
              const char c = values[at++];
              if (c >= '0' && c <= '9')
                value = std::min<std::size_t>(value * 10 + static_cast<std::size_t>(c - '0'), 1u << 30);
            }
            if (value > MeshLimits::kMaxPolygonCorners) polygonTooLarge(file, line(*element), value);
          }
        } else {
          const std::size_t pCorners = countTokens(values) / indicesPerCorner(*parent);
          if (std::strcmp(parent->Name(), "polygons") == 0 && pCorners > MeshLimits::kMaxPolygonCorners)
            polygonTooLarge(file, line(*element), pCorners);
          corners += pCorners;
          if (corners > kMaxCorners) tooManyCorners(file, line(*element));
        }
      }
    }
    for (const auto* child = element->LastChildElement(); child; child = child->PreviousSiblingElement())
      pending.push_back(child);
  }
  checkNodeGraph(nodeGraph(nodes), file);
}

}  // namespace pmdplan::mesh_scan
