// Writing meshes for printers, Blender and MeshLab: binary STL (a facet normal per triangle,
// no shared vertices: what slicers read), binary little-endian PLY (welded vertices with their
// normals and orbit colours) and Wavefront OBJ (text, with normals). All go through AtomicFile,
// so a file is whole or absent.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/mesh/mesh.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {

enum class MeshFormat { Stl, Ply, Obj };

// From the extension, in any case: .stl, .ply or .obj. Throws UserError(path, ...) for any
// other, naming the three.
MeshFormat meshFormatFromPath(const std::string& path);
const char* meshFormatName(MeshFormat format);  // "stl", "ply", "obj"

// Writes the whole mesh to `file` (which the caller commits). Normals and colours are written
// where the format has room for them and the mesh has them.
void writeMesh(const Mesh& mesh, MeshFormat format, AtomicFile& file);
// The same bytes in memory (for the explorer's mesh download).
std::vector<uint8_t> encodeMesh(const Mesh& mesh, MeshFormat format);

}  // namespace quaternia
