#pragma once
// Internal: the scans of a mesh file's bytes made before assimp reads them (mesh_file.hpp), so
// that no file within MeshLimits::kMaxFileBytes makes assimp build millions of faces or recurse
// without end. Each throws InputError naming the file and what breaks MeshLimits.
#include <string>
#include <string_view>

namespace pmdplan::mesh_scan {

/// OBJ: at most MeshLimits::kMaxPolygonCorners corners per face, and at most 3 corners per allowed
/// triangle over every face, line and point element (a polygon of n corners makes n - 2 triangles).
void checkObj(std::string_view bytes, const std::string& file);

/// STL: a binary STL (80-byte header, count, 50 bytes a triangle) claims at most
/// MeshLimits::kMaxTriangles triangles. An ASCII STL needs no scan (it has ~80 bytes a triangle).
void checkStl(std::string_view bytes, const std::string& file);

/// COLLADA: well-formed XML; the node graph (children and <instance_node>) without cycles, nested at
/// most kMaxColladaNodeDepth deep and at most kMaxColladaNodeInstances nodes expanded; the
/// primitives' <p> index lists name at most 3 corners per allowed triangle, and no <vcount> entry
/// more than kMaxPolygonCorners.
void checkCollada(std::string_view bytes, const std::string& file);

}  // namespace pmdplan::mesh_scan
