#include "io/gmsh_msh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace polymech::io {

namespace {

// Line-by-line reader that knows where it is, for error messages.
class MshReader {
 public:
  explicit MshReader(const std::filesystem::path& file) : file_(file), in_(file) {
    if (!std::filesystem::exists(file)) throw MeshError(file.string() + ": mesh file not found");
    if (!in_) throw MeshError(file.string() + ": cannot open the mesh file");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(file_.string() + ":" + std::to_string(line_no_) + ": " + what);
  }
  std::string where() const { return file_.filename().string() + ":" + std::to_string(line_no_); }
  int line_number() const { return line_no_; }

  // Next non-empty line; false at the end of the file.
  bool next(std::string& line) {
    while (std::getline(in_, line)) {
      ++line_no_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.find_first_not_of(" \t") != std::string::npos) return true;
    }
    return false;
  }
  std::string expect_line(const std::string& context) {
    std::string line;
    if (!next(line)) fail("unexpected end of file in " + context);
    return line;
  }
  // The integers of the next line, exactly `count` of them (count < 0: any number >= 1).
  std::vector<long long> integers(const std::string& context, int count) {
    const std::string line = expect_line(context);
    std::istringstream s(line);
    std::vector<long long> out;
    std::string tok;
    while (s >> tok) {
      char* end = nullptr;
      const long long v = std::strtoll(tok.c_str(), &end, 10);
      if (end == tok.c_str() || *end != '\0') fail("'" + tok + "' is not an integer (" + context + ")");
      out.push_back(v);
    }
    if (count >= 0 && static_cast<int>(out.size()) != count)
      fail("expected " + std::to_string(count) + " integers (" + context + "), found " + std::to_string(out.size()));
    if (out.empty()) fail("expected integers (" + context + ")");
    return out;
  }
  // A count read from the file: refused if negative or beyond `limit` (a corrupted header).
  long long count(long long v, const std::string& what, long long limit = 2000000000LL) const {
    if (v < 0 || v > limit)
      fail(what + " = " + std::to_string(v) + " is out of range; allowed: 0 .. " + std::to_string(limit) +
           " (is the file corrupted?)");
    return v;
  }
  std::vector<double> reals(const std::string& context, int count) {
    const std::string line = expect_line(context);
    std::istringstream s(line);
    std::vector<double> out;
    std::string tok;
    while (s >> tok) {
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0') fail("'" + tok + "' is not a number (" + context + ")");
      if (!std::isfinite(v)) fail("'" + tok + "' is not a finite number (" + context + ")");
      out.push_back(v);
    }
    if (static_cast<int>(out.size()) < count)
      fail("expected " + std::to_string(count) + " numbers (" + context + "), found " + std::to_string(out.size()));
    return out;
  }
  void expect_end(const std::string& section) {
    const std::string line = expect_line("section " + section);
    if (trim(line) != "$End" + section.substr(1)) fail("expected $End" + section.substr(1) + ", found '" + trim(line) + "'");
  }
  static std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
  }

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  int line_no_ = 0;
};

std::string element_type_name(long long t) {
  switch (t) {
    case 1: return "2-node line";
    case 2: return "3-node triangle";
    case 3: return "4-node quadrangle";
    case 4: return "4-node tetrahedron";
    case 5: return "8-node hexahedron";
    case 6: return "6-node prism";
    case 7: return "5-node pyramid";
    case 10: return "9-node quadrangle";
    case 11: return "10-node tetrahedron";
    case 12: return "27-node hexahedron";
    case 15: return "1-node point";
    case 16: return "8-node quadrangle";
    case 17: return "20-node hexahedron";
    default: return "element type " + std::to_string(t);
  }
}

int node_count(long long type) {
  switch (type) {
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    case 4: return 4;
    case 5: return 8;
    case 6: return 6;
    case 7: return 5;
    case 8: return 3;
    case 9: return 6;
    case 10: return 9;
    case 11: return 10;
    case 12: return 27;
    case 15: return 1;
    case 16: return 8;
    case 17: return 20;
    default: return -1;
  }
}

}  // namespace

mesh::Mesh read_gmsh_mesh(const std::filesystem::path& file) {
  MshReader r(file);
  mesh::Mesh mesh;
  mesh.file = file.string();
  std::map<std::pair<int, int>, std::string> physical_names;  // (dim, tag) -> name
  std::map<int, std::vector<int>> surface_physicals;          // surface entity -> physical tags
  std::unordered_map<long long, std::int64_t> node_index;     // node tag -> vertex index
  bool have_format = false, have_nodes = false, have_elements = false, have_entities = false;
  std::string line;
  while (r.next(line)) {
    const std::string section = MshReader::trim(line);
    if (section == "$MeshFormat") {
      if (have_format) r.fail("a second $MeshFormat section; allowed: one");
      const std::string l = r.expect_line("$MeshFormat");
      std::istringstream s(l);
      std::string version;
      int file_type = -1, data_size = 0;
      s >> version >> file_type >> data_size;
      if (version.rfind("4.1", 0) != 0)
        r.fail("MSH version " + version + " is not supported; allowed: 4.1 (write it with gmsh -format msh41)");
      if (file_type != 0) r.fail("binary MSH files are not supported; allowed: ASCII (file-type 0)");
      r.expect_end("$MeshFormat");
      have_format = true;
    } else if (section == "$PhysicalNames") {
      const long long n = r.count(r.integers("the number of physical names", 1)[0], "the number of physical names");
      for (long long i = 0; i < n; ++i) {
        const std::string l = r.expect_line("$PhysicalNames");
        std::istringstream s(l);
        int dim = -1, tag = -1;
        s >> dim >> tag;
        const auto q0 = l.find('"'), q1 = l.rfind('"');
        if (s.fail() || q0 == std::string::npos || q1 == q0) r.fail("expected: dimension tag \"name\"");
        physical_names[{dim, tag}] = l.substr(q0 + 1, q1 - q0 - 1);
      }
      r.expect_end("$PhysicalNames");
    } else if (section == "$Entities") {
      if (!have_format) r.fail("$Entities before $MeshFormat");
      const auto counts = r.integers("numPoints numCurves numSurfaces numVolumes", 4);
      for (int dim = 0; dim < 4; ++dim) r.count(counts[dim], "the number of entities of dimension " + std::to_string(dim));
      for (int dim = 0; dim < 4; ++dim)
        for (long long i = 0; i < counts[dim]; ++i) {
          const std::string l = r.expect_line("$Entities");
          std::istringstream s(l);
          long long tag = 0;
          double skip = 0;
          s >> tag;
          for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) s >> skip;  // point: x y z; others: bounding box
          long long nphys = 0;
          s >> nphys;
          if (s.fail() || nphys < 0) r.fail("malformed entity line (dimension " + std::to_string(dim) + ")");
          std::vector<int> phys;
          // read as many as the line holds: a count of 2e9 on a short line must not allocate for 2e9 (issue 33 item 11)
          for (long long k = 0; k < nphys; ++k) {
            long long p = 0;
            if (!(s >> p))
              r.fail("malformed entity line: it announces " + std::to_string(nphys) + " physical tags and holds " +
                     std::to_string(k));
            phys.push_back(static_cast<int>(std::llabs(p)));
          }
          if (dim == 2) surface_physicals[static_cast<int>(tag)] = phys;
        }
      r.expect_end("$Entities");
      have_entities = true;
    } else if (section == "$PartitionedEntities") {
      r.fail("partitioned meshes are not supported; allowed: a single-part mesh (gmsh without -part)");
    } else if (section == "$Nodes") {
      if (have_nodes) r.fail("a second $Nodes section; allowed: one");
      if (!have_format) r.fail("$Nodes before $MeshFormat");
      const auto head = r.integers("numEntityBlocks numNodes minNodeTag maxNodeTag", 4);
      r.count(head[0], "numEntityBlocks");
      const long long total = r.count(head[1], "numNodes");
      mesh.nodes.reserve(static_cast<std::size_t>(3 * std::min(total, 1000000LL)));
      for (long long b = 0; b < head[0]; ++b) {
        const auto block = r.integers("entityDim entityTag parametric numNodesInBlock", 4);
        const long long n = r.count(block[3], "numNodesInBlock", total - mesh.node_count());
        const bool parametric = block[2] != 0;
        std::vector<long long> tags(static_cast<std::size_t>(n));
        for (long long i = 0; i < n; ++i) tags[i] = r.integers("a node tag", 1)[0];
        for (long long i = 0; i < n; ++i) {
          const auto x = r.reals("node coordinates x y z", 3);
          if (!parametric && x.size() != 3) r.fail("expected 3 coordinates (x y z)");
          if (!node_index.emplace(tags[i], mesh.node_count()).second)
            r.fail("node tag " + std::to_string(tags[i]) + " appears twice");
          for (int k = 0; k < 3; ++k) mesh.nodes.push_back(x[k]);
        }
      }
      if (mesh.node_count() != head[1])
        r.fail("$Nodes announced " + std::to_string(head[1]) + " nodes, found " + std::to_string(mesh.node_count()));
      r.expect_end("$Nodes");
      have_nodes = true;
    } else if (section == "$Elements") {
      if (have_elements) r.fail("a second $Elements section; allowed: one");
      if (!have_nodes) r.fail("$Elements before $Nodes");
      const auto head = r.integers("numEntityBlocks numElements minElementTag maxElementTag", 4);
      r.count(head[0], "numEntityBlocks");
      r.count(head[1], "numElements");
      for (long long b = 0; b < head[0]; ++b) {
        const auto block = r.integers("entityDim entityTag elementType numElementsInBlock", 4);
        const long long dim = block[0], entity = block[1], type = block[2], n = r.count(block[3], "numElementsInBlock");
        const int nn = node_count(type);
        if (nn < 0) r.fail("unknown element type " + std::to_string(type));
        const bool keep_hex = dim == 3 && type == 5;
        const bool keep_facet = dim == 2 && (type == 3 || type == 2);
        if (dim == 3 && !keep_hex)
          r.fail(element_type_name(type) + " elements are not supported; allowed in volumes: 8-node hexahedra (type 5)");
        int boundary = -1;
        if (dim == 2) {
          const auto it = surface_physicals.find(static_cast<int>(entity));
          const std::vector<int> phys = it == surface_physicals.end() ? std::vector<int>{} : it->second;
          std::vector<std::string> names;
          for (int p : phys) {
            auto nm = physical_names.find({2, p});
            names.push_back(nm != physical_names.end() ? nm->second : "physical " + std::to_string(p));
          }
          if (names.size() > 1)
            r.fail("surface " + std::to_string(entity) + " belongs to " + std::to_string(names.size()) +
                   " physical groups; a boundary face needs exactly one name");
          if (names.size() == 1) {
            if (!keep_facet)
              r.fail(element_type_name(type) + " elements on the physical surface '" + names[0] +
                     "' are not supported; allowed on surfaces: 4-node quadrangles (type 3), 3-node triangles (type 2)");
            boundary = mesh.group_index(names[0]);
            if (boundary < 0) {
              boundary = static_cast<int>(mesh.groups.size());
              mesh.groups.push_back(names[0]);
            }
          }
        }
        for (long long i = 0; i < n; ++i) {
          const auto v = r.integers("elementTag nodeTag ...", nn + 1);
          if (!keep_hex && boundary < 0) continue;  // points, lines, untagged surfaces
          std::array<std::int64_t, 8> ids{};
          for (int k = 0; k < nn; ++k) {
            const auto it = node_index.find(v[k + 1]);
            if (it == node_index.end())
              r.fail("element " + std::to_string(v[0]) + " refers to node " + std::to_string(v[k + 1]) +
                     ", which is not in $Nodes");
            ids[k] = it->second;
          }
          const std::string origin = file.string() + ":" + std::to_string(r.line_number());
          if (keep_hex) {
            std::set<std::int64_t> distinct(ids.begin(), ids.end());
            if (distinct.size() != 8) r.fail("hexahedron " + std::to_string(v[0]) + " repeats a node (degenerate)");
            mesh::Hexahedron h;
            for (int k = 0; k < 8; ++k) h.nodes[k] = ids[k];
            h.origin = origin;
            h.tag = v[0];
            mesh.hexahedra.push_back(h);
          } else {
            mesh::Facet f;
            for (int k = 0; k < nn; ++k) f.nodes[k] = ids[k];
            f.corners = nn;
            f.group = boundary;
            f.origin = origin;
            f.tag = v[0];
            mesh.facets.push_back(f);
          }
        }
      }
      r.expect_end("$Elements");
      have_elements = true;
    } else if (!section.empty() && section[0] == '$') {
      // another section ($NodeData, $Periodic, ...): skip to its end
      const std::string end = "$End" + section.substr(1);
      std::string l;
      bool closed = false;
      while (r.next(l))
        if (MshReader::trim(l) == end) {
          closed = true;
          break;
        }
      if (!closed) r.fail("section " + section + " is not closed by " + end);
    } else {
      r.fail("expected a section header ($MeshFormat, $Nodes, $Elements, ...), found '" + section + "'");
    }
  }
  if (!have_format) throw MeshError(file.string() + ": no $MeshFormat section: not a Gmsh MSH file");
  if (!have_nodes || !have_elements) throw MeshError(file.string() + ": no $Nodes or $Elements section");
  (void)have_entities;
  return mesh;
}

}  // namespace polymech::io
