#include "parallel/mesh_file_pieces.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "base/error.hpp"
#include "geom/box.hpp"
#include "io/gamma_keywords.hpp"
#include "io/gamma_mesh.hpp"
#include "io/record_run.hpp"
#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"
#include "parallel/line_ids_by_ends.hpp"
#include "parallel/part_shipment.hpp"

namespace hocav {
namespace {

// A vertex as the process that read it answers for it.
template <int D>
struct VertexAnswer {
  Vec<D> point;
  std::int32_t ref;
  std::int32_t on_facet;  // a facet of the file uses it
};

// An element face sent to where it meets the others with its key.
template <int D>
struct FaceRecord {
  FaceKey<D> key;
  Index element;       // the file id of its element (the smaller, when two of the run have it)
  std::int32_t sides;  // the elements of the run that have it: 1 or 2
};

// A facet of the file, sent to where it meets its face, then to the run of its element.
template <int D>
struct FacetRecord {
  typename Mesh<D>::Facet vertices;  // file vertex ids, in the file's order
  Index id;                          // its file id
  Index element;                     // the file id of the element it goes with, once met
  std::int32_t ref;
};

bool listed(const std::vector<Index>& sorted, Index id) { return std::binary_search(sorted.begin(), sorted.end(), id); }

std::vector<Index> sorted(std::vector<Index> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

// The name of the P1 keyword of simplices of a dimension (Tetrahedra, Triangles, Edges).
std::string p1_keyword(int simplex_dimension) { return gamma::keyword_name(gamma::simplex_keyword(simplex_dimension, 1).code); }

// Per vertex of this process's run: whether a facet of any run uses it.
template <int D>
std::vector<char> facet_vertex_flags(const GammaMeshSlice<D>& slice) {
  std::vector<std::vector<Index>> outgoing(static_cast<std::size_t>(process_count()));
  for (const auto& facet : slice.facets)
    for (Index v : facet) outgoing[slice_holding(v, slice.vertex_count, process_count())].push_back(v);
  std::vector<char> flags(slice.points.size(), 0);
  for (Index v : exchange_values_joined(outgoing)) flags[v - slice.first_vertex] = 1;
  return flags;
}

// The vertices `ids` (sorted file ids), from the processes whose runs hold them.
template <int D>
std::vector<VertexAnswer<D>> fetched_vertices(const GammaMeshSlice<D>& slice, const std::vector<char>& on_facet,
                                              const std::vector<Index>& ids) {
  std::vector<std::vector<Index>> asked(static_cast<std::size_t>(process_count()));
  for (Index v : ids) asked[slice_holding(v, slice.vertex_count, process_count())].push_back(v);
  std::vector<std::vector<VertexAnswer<D>>> answers;
  for (const std::vector<Index>& ids_asked : exchange_values(asked)) {
    answers.emplace_back();
    for (Index v : ids_asked) {
      const Index at = v - slice.first_vertex;
      answers.back().push_back({slice.points[at], slice.point_refs[at], on_facet[at]});
    }
  }
  return exchange_values_joined(answers);  // in rank order: the order of `ids`, the runs being ascending
}

// The faces of a run's elements: which another element of the run has, and those to send where they
// meet the other runs' faces and the facets: every open face, and a closed one (once) when a facet
// may lie on it (its vertices are facets').
template <int D>
struct RunFaces {
  std::vector<char> closed;  // per element face
  std::vector<FaceRecord<D>> sent;
  std::vector<std::size_t> sent_face;  // per sent record, its element face
};

// The places of file ids in `ids` (sorted, unique): a table over their range when it is compact (a
// run of a file in spatial order), else a binary search.
class LocalIds {
 public:
  explicit LocalIds(const std::vector<Index>& ids) : ids_(ids) {
    if (ids.empty() || static_cast<std::size_t>(ids.back() - ids.front()) >= 4 * ids.size()) return;
    table_.assign(static_cast<std::size_t>(ids.back() - ids.front()) + 1, kNoIndex);
    for (std::size_t i = 0; i < ids.size(); ++i) table_[static_cast<std::size_t>(ids[i] - ids.front())] = static_cast<Index>(i);
  }
  Index operator()(Index id) const {
    if (!table_.empty()) return table_[static_cast<std::size_t>(id - ids_.front())];
    return static_cast<Index>(std::lower_bound(ids_.begin(), ids_.end(), id) - ids_.begin());
  }

 private:
  const std::vector<Index>& ids_;
  std::vector<Index> table_;
};

// The run's elements by their vertices' places in `ids`, with their topology: which faces another
// element of the run has.
template <int D>
Mesh<D> run_mesh(const GammaMeshSlice<D>& slice, const std::vector<Index>& ids, const std::vector<VertexAnswer<D>>& vertices,
                 const std::string& path) {
  Mesh<D> mesh;
  for (const VertexAnswer<D>& vertex : vertices) mesh.add_vertex(vertex.point, vertex.ref);
  const LocalIds local_of(ids);
  for (const auto& element : slice.elements) {
    typename Mesh<D>::Element local{};
    for (int i = 0; i <= D; ++i) local[i] = local_of(element[i]);
    mesh.add_element(local, 0);
  }
  try {
    mesh.build_topology();
  } catch (const Error& error) {
    throw Error(path + ": " + p1_keyword(D) + ": " + error.what() + " (elements counted from entity " + one_based(slice.first_element) +
                ")");
  }
  return mesh;
}

template <int D>
RunFaces<D> run_faces(const GammaMeshSlice<D>& slice, const std::vector<Index>& ids, const std::vector<VertexAnswer<D>>& vertices,
                      const std::string& path) {
  const Mesh<D> mesh = run_mesh(slice, ids, vertices, path);
  RunFaces<D> faces{std::vector<char>(slice.elements.size() * (D + 1), 0), {}, {}};
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      const Index other = mesh.neighbor(k, face);
      const std::size_t at = static_cast<std::size_t>(k) * (D + 1) + static_cast<std::size_t>(face);
      faces.closed[at] = other != kNoIndex;
      FaceKey<D> key{};
      for (int i = 0; i < D; ++i) key[i] = mesh.element(k)[face_vertices<D>(face)[i]];
      const bool on_facets = std::all_of(key.begin(), key.end(), [&](Index v) { return vertices[v].on_facet != 0; });
      if (other != kNoIndex && (other < k || !on_facets)) continue;  // a closed face once, when a facet may lie on it
      for (Index& v : key) v = ids[v];
      faces.sent.push_back({sorted_key<D>(key), slice.first_element + k, other != kNoIndex ? 2 : 1});
      faces.sent_face.push_back(at);
    }
  return faces;
}

// What the meeting tells a run: per sent face, whether an element of another run lies across it;
// the file's facets on the run's elements.
template <int D>
struct Met {
  std::vector<char> across;
  std::vector<FacetRecord<D>> facets;
};

// The faces met at one process: per key, the elements that have it and the smallest of them.
template <int D>
struct Meeting {
  struct Sides {
    std::int32_t count = 0;
    Index element = kNoIndex;
  };
  std::unordered_map<FaceKey<D>, Sides, FaceKeyHash<D>> by_key;
  std::vector<std::vector<FaceRecord<D>>> arrived;  // per process

  Meeting(std::vector<std::vector<FaceRecord<D>>> messages, const std::string& path) : arrived(std::move(messages)) {
    for (const std::vector<FaceRecord<D>>& faces : arrived) {
      for (const FaceRecord<D>& face : faces) {
        Sides& sides = by_key[face.key];
        sides.count += face.sides;
        sides.element = sides.count == face.sides ? face.element : std::min(sides.element, face.element);
        if (sides.count > 2)
          throw Error(path + ": " + p1_keyword(D) + ": entity " + one_based(sides.element) + " has a face two other elements have");
      }
    }
  }

  // Per process, per face it sent: whether two elements have it.
  std::vector<std::vector<char>> answers() const {
    std::vector<std::vector<char>> out;
    for (const std::vector<FaceRecord<D>>& faces : arrived) {
      out.emplace_back();
      for (const FaceRecord<D>& face : faces) out.back().push_back(by_key.at(face.key).count == 2);
    }
    return out;
  }
};

// Every process at once: the runs' faces and facets meet where their keys hash to.
template <int D>
Met<D> meet(const GammaMeshSlice<D>& slice, const RunFaces<D>& faces, const std::string& path) {
  const int processes = process_count();
  std::vector<std::vector<FaceRecord<D>>> face_messages(static_cast<std::size_t>(processes));
  std::vector<std::vector<std::size_t>> positions(face_messages.size());  // per message, its records' places in `sent`
  for (std::size_t i = 0; i < faces.sent.size(); ++i) {
    const int to = meeting_process<D>(faces.sent[i].key, processes);
    face_messages[to].push_back(faces.sent[i]);
    positions[to].push_back(i);
  }
  std::vector<std::vector<FacetRecord<D>>> facet_messages(face_messages.size());
  for (std::size_t f = 0; f < slice.facets.size(); ++f)
    facet_messages[meeting_process<D>(sorted_key<D>(slice.facets[f]), processes)].push_back(
        {slice.facets[f], slice.first_facet + static_cast<Index>(f), kNoIndex, slice.facet_refs[f]});
  const Meeting<D> meeting(exchange_values(face_messages), path);
  std::vector<std::vector<FacetRecord<D>>> placed(face_messages.size());
  for (FacetRecord<D> facet : exchange_values_joined(facet_messages)) {
    const auto sides = meeting.by_key.find(sorted_key<D>(facet.vertices));
    if (sides == meeting.by_key.end())
      throw Error(path + ": " + p1_keyword(D - 1) + ": entity " + one_based(facet.id) + " is no face of the elements");
    facet.element = sides->second.element;
    placed[slice_holding(facet.element, slice.element_count, processes)].push_back(facet);
  }
  Met<D> met{std::vector<char>(faces.sent.size(), 0), exchange_values_joined(placed)};
  const std::vector<std::vector<char>> answers = exchange_values(meeting.answers());
  for (std::size_t from = 0; from < answers.size(); ++from)
    for (std::size_t j = 0; j < answers[from].size(); ++j) met.across[positions[from][j]] = answers[from][j];
  std::sort(met.facets.begin(), met.facets.end(), [](const FacetRecord<D>& a, const FacetRecord<D>& b) { return a.id < b.id; });
  return met;
}

// The tags of the file, sorted for lookups.
struct SortedTags {
  std::vector<Index> corners, ridges, required_vertices, required_edges, required_triangles;
  template <int D>
  explicit SortedTags(const GammaMeshSlice<D>& slice)
      : corners(sorted(slice.corners)),
        ridges(sorted(slice.ridges)),
        required_vertices(sorted(slice.required_vertices)),
        required_edges(sorted(slice.required_edges)),
        required_triangles(sorted(slice.required_triangles)) {}
};

// 3D: the file's lines along the edges of the run's elements (`s.elements`), with their tags. The
// lines are few: the element edges are looked up among them, not the other way round.
template <int D>
void add_run_lines(Shipment<D>& s, const GammaMeshSlice<D>& slice, const SortedTags& tags) {
  std::unordered_set<std::uint64_t> line_keys, found;
  for (const auto& line : slice.lines) line_keys.insert(Mesh<D>::edge_key(line[0], line[1]));
  if (line_keys.empty()) return;
  for (const auto& element : s.elements)
    for (int e = 0; e < Simplex<D>::kEdges; ++e)
      if (const std::uint64_t key = Mesh<D>::edge_key(element[edge_vertices<D>(e)[0]], element[edge_vertices<D>(e)[1]]);
          line_keys.count(key))
        found.insert(key);
  for (std::size_t l = 0; l < slice.lines.size(); ++l) {
    if (!found.count(Mesh<D>::edge_key(slice.lines[l][0], slice.lines[l][1]))) continue;
    s.lines.push_back(slice.lines[l]);
    s.line_refs.push_back(slice.line_refs[l]);
    const auto id = static_cast<Index>(l);
    s.line_flags.push_back(
        static_cast<char>((listed(tags.required_edges, id) ? kShippedRequired : 0) | (listed(tags.ridges, id) ? kShippedRidge : 0)));
  }
}

// The run's own shipment: its elements (moved out of `slice`) with what the part needs around them.
template <int D>
Shipment<D> run_shipment(GammaMeshSlice<D>& slice, const std::vector<Index>& ids, const std::vector<VertexAnswer<D>>& vertices,
                         const RunFaces<D>& faces, const Met<D>& met) {
  const SortedTags tags(slice);
  Shipment<D> s;
  s.vertex_ids = ids;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    s.points.push_back(vertices[i].point);
    s.vertex_refs.push_back(vertices[i].ref);
    const char pinned = listed(tags.required_vertices, ids[i]) ? kPinnedByMesh : 0;
    s.vertex_flags.push_back(static_cast<char>((listed(tags.corners, ids[i]) ? kShippedCorner : 0) | (pinned << 1)));
  }
  std::vector<char> inner = faces.closed;
  for (std::size_t i = 0; i < faces.sent.size(); ++i)
    if (met.across[i]) inner[faces.sent_face[i]] = 1;
  s.elements = std::move(slice.elements);
  s.element_refs = std::move(slice.element_refs);
  for (std::size_t k = 0; k < s.elements.size(); ++k) {
    char bits = 0;
    for (int face = 0; face <= D; ++face)
      if (inner[k * (D + 1) + static_cast<std::size_t>(face)]) bits = static_cast<char>(bits | (1 << face));
    s.inner_faces.push_back(bits);
  }
  // Facets: 3D RequiredTriangles name them; 2D RequiredEdges and Ridges (its Edges are the facets).
  for (const FacetRecord<D>& facet : met.facets) {
    s.facets.push_back(facet.vertices);
    s.facet_refs.push_back(facet.ref);
    const bool required = listed(D == 3 ? tags.required_triangles : tags.required_edges, facet.id);
    const bool ridge = D == 2 && listed(tags.ridges, facet.id);
    s.facet_flags.push_back(static_cast<char>((required ? kShippedRequired : 0) | (ridge ? kShippedRidge : 0)));
  }
  if constexpr (D == 3) add_run_lines(s, slice, tags);
  return s;
}

// Every process at once: the shipment of its own run (the slice's elements moved into it), and the
// file ids of its facets in `facet_ids`; what was needed to make it is gone when it returns.
template <int D>
Shipment<D> own_shipment(GammaMeshSlice<D>& slice, const std::string& path, std::vector<Index>& facet_ids) {
  const std::vector<char> on_facet = facet_vertex_flags(slice);
  std::vector<Index> ids;
  for (const auto& element : slice.elements) ids.insert(ids.end(), element.begin(), element.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ids.shrink_to_fit();
  const std::vector<VertexAnswer<D>> vertices = fetched_vertices(slice, on_facet, ids);
  const RunFaces<D> faces = run_faces(slice, ids, vertices, path);
  const Met<D> met = meet(slice, faces, path);
  for (const FacetRecord<D>& facet : met.facets) facet_ids.push_back(facet.id);
  return run_shipment(slice, ids, vertices, faces, met);
}

// The file's lines (3D), each by its ends' file ids (the global ids of a piece's vertices) and its
// file id: the slice holds the whole list.
template <int D>
std::vector<KnownLine> file_lines(const GammaMeshSlice<D>& slice) {
  std::vector<KnownLine> lines;
  for (std::size_t l = 0; l < slice.lines.size(); ++l) lines.push_back({sorted_key<2>(slice.lines[l]), static_cast<Index>(l)});
  return lines;
}

}  // namespace

template <int D>
MeshFilePiece<D> read_mesh_file_piece(const std::string& path) {
  GammaMeshSlice<D> slice = read_gamma_mesh_slice<D>(path, process_rank(), process_count());
  MeshFilePiece<D> piece{{}, slice.vertex_count, slice.element_count, slice.facet_count, {}, {}};
  std::vector<Shipment<D>> own;
  own.push_back(own_shipment(slice, path, piece.facet_ids));
  std::vector<KnownLine> lines = file_lines(slice);
  slice = {};
  piece.part = part_of_shipments(own);
  piece.line_ids = line_ids_among(piece.part, std::move(lines));
  piece.facet_ids.resize(static_cast<std::size_t>(piece.part.mesh.facet_count()), kNoIndex);  // the interface facets come after
  return piece;
}

template <int D>
double whole_diagonal(const Mesh<D>& piece) {
  Box<D> own = Box<D>::empty();
  for (const Vec<D>& x : piece.vertices()) own.add(x);
  Box<D> whole = Box<D>::empty();
  for (const Box<D>& each : all_gather_value(own)) whole.add(each);
  return whole.is_empty() ? 0 : norm(whole.upper - whole.lower);
}

template double whole_diagonal(const Mesh<2>&);
template double whole_diagonal(const Mesh<3>&);
template MeshFilePiece<2> read_mesh_file_piece(const std::string&);
template MeshFilePiece<3> read_mesh_file_piece(const std::string&);

}  // namespace hocav
