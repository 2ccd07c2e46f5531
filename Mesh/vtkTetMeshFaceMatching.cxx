/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshFaceMatching.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshFaceMatching.h"

#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuildState.h"
#include "vtkTetMeshOverlapRule.h"
#include "vtkTetMeshValidationReport.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <vector>

namespace
{
constexpr uint32_t NoNeighbor = vtkTetMesh::NoNeighbor;
using FaceEntry = vtkTetMeshBuildState::FaceEntry;

inline bool FaceEntryLess(const FaceEntry& a, const FaceEntry& b)
{
  if (a.Mid != b.Mid)
  {
    return a.Mid < b.Mid;
  }
  if (a.Hi != b.Hi)
  {
    return a.Hi < b.Hi;
  }
  return a.Face < b.Face;
}

inline bool SameFace(const FaceEntry& a, const FaceEntry& b)
{
  return a.Mid == b.Mid && a.Hi == b.Hi;
}

// Tetrahedra in chunks of this many for the passes of a huge mesh (ChunkPasses): a chunk is a
// compact region, mostly within one pass's range of points.
constexpr vtkIdType ChunkTets = 65536;

// Calls f(face, lo, mid, hi) for the four faces of a tetrahedron, lo < mid < hi; faces with a
// repeated point id (collapsed, zero area) are skipped.
template <typename F>
inline void ForEachSortedFace(const uint32_t* ids, uint32_t tet, F&& f)
{
  uint32_t v[4] = { ids[0], ids[1], ids[2], ids[3] };
  uint32_t l[4] = { 0, 1, 2, 3 };
  // Five compare-exchanges sort four values.
  auto cx = [&](int a, int b)
  {
    if (v[b] < v[a])
    {
      std::swap(v[a], v[b]);
      std::swap(l[a], l[b]);
    }
  };
  cx(0, 1);
  cx(2, 3);
  cx(0, 2);
  cx(1, 3);
  cx(1, 2);
  const uint32_t base = tet << 2;
  // Face opposite the point at sorted position k holds the other three, still sorted.
  if (v[1] != v[2] && v[2] != v[3])
  {
    f(base | l[0], v[1], v[2], v[3]);
  }
  if (v[0] != v[2] && v[2] != v[3])
  {
    f(base | l[1], v[0], v[2], v[3]);
  }
  if (v[0] != v[1] && v[1] != v[3])
  {
    f(base | l[2], v[0], v[1], v[3]);
  }
  if (v[0] != v[1] && v[1] != v[2])
  {
    f(base | l[3], v[0], v[1], v[2]);
  }
}

//------------------------------------------------------------------------------
// Pairs the faces of one bucket (faces that share their smallest point id). Two
// non-degenerate tetrahedra on one side of a face overlap (vtkTetMeshOverlapRule).
class BucketPairing
{
public:
  uint32_t* Neighbors;
  const uint8_t* Sides; // bit i of a tetrahedron's byte: the parity of its face i
  const uint8_t* Flags;
  const uint32_t* InputCells;

  bool Side(uint32_t f) const { return ((this->Sides[f >> 2] >> (f & 3u)) & 1u) != 0; }
  bool Overlap(uint32_t a, uint32_t b) const
  {
    return this->Side(a) == this->Side(b) && !(this->Flags[a >> 2] & vtkTetMesh::Degenerate) &&
      !(this->Flags[b >> 2] & vtkTetMesh::Degenerate);
  }

  // The common case: a small open-addressing table, slot -> 1 + index of the first face seen
  // with that key, the top bit set once it is paired. Linear in the bucket's size, where a sort
  // is not, and buckets of meshes numbered at random hold dozens of faces. False when a face
  // has a third tetrahedron or two on one side: the caller then starts the bucket over.
  bool PairByTable(const FaceEntry* first, const FaceEntry* last, std::vector<uint32_t>& table)
  {
    constexpr uint32_t Paired = 0x80000000u;
    const ptrdiff_t n = last - first;
    size_t size = 8;
    while (size < 2 * static_cast<size_t>(n))
    {
      size <<= 1;
    }
    if (table.size() < size)
    {
      table.resize(size);
    }
    std::fill(table.begin(), table.begin() + size, 0u);
    const size_t mask = size - 1;
    for (ptrdiff_t k = 0; k < n; ++k)
    {
      const FaceEntry& e = first[k];
      size_t h = ((e.Mid * 0x9e3779b1u) ^ (e.Hi * 0x85ebca77u)) & mask;
      for (;;)
      {
        const uint32_t slot = table[h];
        if (slot == 0)
        {
          table[h] = static_cast<uint32_t>(k + 1);
          break;
        }
        const FaceEntry& o = first[(slot & ~Paired) - 1];
        if (SameFace(o, e))
        {
          if ((slot & Paired) || this->Overlap(o.Face, e.Face))
          {
            return false;
          }
          this->Neighbors[o.Face] = e.Face;
          this->Neighbors[e.Face] = o.Face;
          table[h] = slot | Paired;
          break;
        }
        h = (h + 1) & mask;
      }
    }
    return true;
  }

  // A face shared by more than two tetrahedra or by two on one side (rare): the bucket over
  // again, sorted, following vtkTetMeshOverlapRule. Returns its non-manifold faces.
  vtkIdType PairSorted(FaceEntry* first, FaceEntry* last,
    std::vector<vtkTetMeshOverlapRule::Entry>& rule, std::vector<uint32_t>& leftOut)
  {
    vtkIdType nonManifold = 0;
    for (FaceEntry* e = first; e < last; ++e)
    {
      this->Neighbors[e->Face] = NoNeighbor;
    }
    std::sort(first, last, FaceEntryLess);
    for (FaceEntry* run = first; run < last;)
    {
      FaceEntry* runEnd = run + 1;
      while (runEnd < last && SameFace(*runEnd, *run))
      {
        ++runEnd;
      }
      const ptrdiff_t m = runEnd - run;
      if (m == 2 && !this->Overlap(run[0].Face, run[1].Face))
      {
        this->Neighbors[run[0].Face] = run[1].Face;
        this->Neighbors[run[1].Face] = run[0].Face;
      }
      else if (m >= 2)
      {
        nonManifold += m > 2 ? 1 : 0;
        rule.clear();
        for (FaceEntry* e = run; e < runEnd; ++e)
        {
          const uint32_t t = e->Face >> 2;
          rule.push_back({ e->Face, this->Side(e->Face),
            (this->Flags[t] & vtkTetMesh::Degenerate) != 0, this->InputCells[t] });
        }
        uint32_t link[2];
        vtkTetMeshOverlapRule::Resolve(rule.data(), rule.size(), link, leftOut);
        if (link[0] != NoNeighbor)
        {
          this->Neighbors[link[0]] = link[1];
          this->Neighbors[link[1]] = link[0];
        }
      }
      run = runEnd;
    }
    return nonManifold;
  }
};
}

//------------------------------------------------------------------------------
void vtkTetMeshFaceMatching::MatchFaces(
  vtkTetMeshBuildState& state, vtkIdType scratchLimit, const std::function<void(double)>& progress)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  mesh->TetNeighbors.assign(4 * static_cast<size_t>(numTets), NoNeighbor);
  state.FaceSides.resize(static_cast<size_t>(numTets));
  vtkSMPTools::Fill(state.FaceSides.begin(), state.FaceSides.end(), uint8_t(0));
  // A face is bucketed by its smallest point id, so the points can be taken in ranges, one
  // pass each: the face entries (12 bytes a face, 48 a tetrahedron) of a huge mesh then take a
  // quarter of that at a time.
  const vtkIdType entryBytes = 4 * numTets * static_cast<vtkIdType>(sizeof(FaceEntry));
  const int passes = entryBytes > scratchLimit ? 4 : 1;
  // Points and tetrahedra are mostly in one spatial order (vtkTetMeshSpatialOrder): a pass's
  // range of points is a region, and the tetrahedra with faces there are mostly a quarter of
  // them. Each pass reads only the chunks that have some.
  vtkTetMeshVector<uint8_t> chunkPasses;
  if (passes > 1)
  {
    ChunkPasses(state, passes, chunkPasses);
  }
  Pairing result;
  for (int pass = 0; pass < passes; ++pass)
  {
    const uint32_t first = static_cast<uint32_t>(numPoints * pass / passes);
    const uint32_t last = static_cast<uint32_t>(numPoints * (pass + 1) / passes);
    BucketFaces(state, first, last, 4 * numTets / passes,
      chunkPasses.empty() ? nullptr : chunkPasses.data(), static_cast<uint8_t>(1u << pass));
    PairFaces(state, last - first, result);
    if (pass + 1 < passes)
    {
      progress(static_cast<double>(pass + 1) / passes);
    }
  }
  vtkTetMeshValidationReport* report = state.GetReport();
  report->SetNumberOfNonManifoldFaces(result.NonManifold);
  report->SetNumberOfOverlappingTetrahedra(
    vtkTetMeshOverlapRule::Apply(result.LeftOut, mesh->TetNeighbors.data(), mesh->TetFlags.data(),
      static_cast<uint8_t>(vtkTetMesh::Overlapping)));
}

//------------------------------------------------------------------------------
// For each chunk of ChunkTets tetrahedra, bit p set where a face of one of them has its smallest
// point id in pass p's range. A face's smallest id is its tetrahedron's smallest or second
// smallest (the face without the smallest point): both are marked, which may mark a pass of no
// face (a degenerate face is never bucketed), never misses one.
void vtkTetMeshFaceMatching::ChunkPasses(
  vtkTetMeshBuildState& state, int passes, vtkTetMeshVector<uint8_t>& chunkPasses)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const uint64_t numPoints = static_cast<uint64_t>(mesh->GetNumberOfPoints());
  const uint32_t* tp = mesh->TetPoints.data();
  const vtkIdType chunks = (numTets + ChunkTets - 1) / ChunkTets;
  chunkPasses.resize(static_cast<size_t>(chunks));
  auto passOf = [passes, numPoints](uint32_t id)
  {
    int p = 0;
    while (p + 1 < passes && id >= numPoints * static_cast<uint64_t>(p + 1) / passes)
    {
      ++p;
    }
    return p;
  };
  vtkSMPTools::For(0, chunks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        uint8_t bits = 0;
        const vtkIdType last = std::min(numTets, (c + 1) * ChunkTets);
        for (vtkIdType t = c * ChunkTets; t < last; ++t)
        {
          const uint32_t* ids = tp + 4 * t;
          const uint32_t lo01 = std::min(ids[0], ids[1]), hi01 = std::max(ids[0], ids[1]);
          const uint32_t lo23 = std::min(ids[2], ids[3]), hi23 = std::max(ids[2], ids[3]);
          const uint32_t smallest = std::min(lo01, lo23);
          const uint32_t second = std::min(std::max(lo01, lo23), std::min(hi01, hi23));
          bits |= static_cast<uint8_t>((1u << passOf(smallest)) | (1u << passOf(second)));
        }
        chunkPasses[static_cast<size_t>(c)] = bits;
      }
    });
}

namespace
{
// The tetrahedra of [begin, end) in chunks that have faces in the pass (`passBit`), each
// given to `f` (all of them without `chunkPasses`).
template <typename F>
void ForTetsOfPass(
  vtkIdType begin, vtkIdType end, const uint8_t* chunkPasses, uint8_t passBit, F&& f)
{
  const vtkIdType chunk = ChunkTets;
  for (vtkIdType t = begin; t < end;)
  {
    const vtkIdType chunkEnd = std::min(end, (t / chunk + 1) * chunk);
    if (!chunkPasses || (chunkPasses[t / chunk] & passBit))
    {
      for (; t < chunkEnd; ++t)
      {
        f(t);
      }
    }
    t = chunkEnd;
  }
}
}

//------------------------------------------------------------------------------
// The counting sort of the faces whose smallest point id is in [first, last) by that id into
// state.FaceEntries (bucket first + v from BucketStarts[v]), and their sides into
// state.FaceSides. `faces` is about how many there are (for the per-block counters' size).
void vtkTetMeshFaceMatching::BucketFaces(vtkTetMeshBuildState& state, uint32_t first, uint32_t last,
  vtkIdType faces, const uint8_t* chunkPasses, uint8_t passBit)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  const size_t numPoints = static_cast<size_t>(last - first);
  const uint32_t* tp = mesh->TetPoints.data();

  // Per-block counters cost blocks * numPoints words: keep that below the faces themselves.
  int blocks = vtkTetMeshBuildState::NumberOfBlocks(numTets);
  const size_t maxBlocks =
    std::max<size_t>(1, static_cast<size_t>(faces) / std::max<size_t>(1, numPoints));
  blocks = static_cast<int>(std::min<size_t>(static_cast<size_t>(blocks), maxBlocks));

  vtkTetMeshVector<uint32_t>& counts = state.FaceCounts;
  counts.resize(static_cast<size_t>(blocks) * numPoints);
  vtkSMPTools::Fill(counts.begin(), counts.end(), 0u);
  vtkTetMeshBuildState::ForBlocks(numTets, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      uint32_t* count = counts.data() + static_cast<size_t>(b) * numPoints;
      ForTetsOfPass(begin, end, chunkPasses, passBit,
        [&](vtkIdType t)
        {
          ForEachSortedFace(tp + 4 * t, static_cast<uint32_t>(t),
            [&](uint32_t, uint32_t lo, uint32_t, uint32_t)
            {
              if (lo - first < numPoints) // unsigned: lo in [first, last)
              {
                ++count[lo - first];
              }
            });
        });
    });
  const uint64_t running = PrefixSums(state, blocks, numPoints);
  if (state.FaceEntries.size() < running)
  {
    state.FaceEntries.resize(static_cast<size_t>(running));
  }
  FaceEntry* entries = state.FaceEntries.data();
  // The side of each face (bit i of a tetrahedron's byte: FaceParity of face i), while its
  // points are in cache: matching then tells overlapping pairs apart without reading them.
  uint8_t* sides = state.FaceSides.data();
  vtkTetMeshBuildState::ForBlocks(numTets, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      uint32_t* offset = counts.data() + static_cast<size_t>(b) * numPoints;
      ForTetsOfPass(begin, end, chunkPasses, passBit,
        [&](vtkIdType t)
        {
          uint8_t side = 0;
          ForEachSortedFace(tp + 4 * t, static_cast<uint32_t>(t),
            [&](uint32_t face, uint32_t lo, uint32_t mid, uint32_t hi)
            {
              if (lo - first >= numPoints)
              {
                return; // another pass's
              }
              FaceEntry& e = entries[offset[lo - first]++];
              e.Mid = mid;
              e.Hi = hi;
              e.Face = face;
              side |= static_cast<uint8_t>(FaceParity(tp, face) ? 1u << (face & 3u) : 0u);
            });
          sides[t] |= side;
        });
    });
}

//------------------------------------------------------------------------------
// The exclusive prefix sums of the per-block counts in (point, block) order: state.BucketStarts
// (numPoints + 1 bucket starts) and, in place of each count, that block's first write position
// in its bucket. Returns the number of faces. In parallel by ranges of points (their totals
// summed first): on one thread this strided pass over blocks x points words took seconds per
// pass at a billion tetrahedra.
uint64_t vtkTetMeshFaceMatching::PrefixSums(
  vtkTetMeshBuildState& state, int blocks, size_t numPoints)
{
  uint32_t* counts = state.FaceCounts.data();
  vtkTetMeshVector<uint64_t>& start = state.BucketStarts;
  start.resize(numPoints + 1);
  const vtkIdType n = static_cast<vtkIdType>(numPoints);
  const int ranges = vtkTetMeshBuildState::NumberOfBlocks(n * blocks);
  std::vector<uint64_t> rangeStart(static_cast<size_t>(ranges) + 1, 0);
  vtkTetMeshBuildState::ForBlocks(n, ranges,
    [&](int r, vtkIdType begin, vtkIdType end)
    {
      uint64_t sum = 0;
      for (int b = 0; b < blocks; ++b)
      {
        const uint32_t* count = counts + static_cast<size_t>(b) * numPoints;
        for (vtkIdType v = begin; v < end; ++v)
        {
          sum += count[v];
        }
      }
      rangeStart[r + 1] = sum;
    });
  std::partial_sum(rangeStart.begin(), rangeStart.end(), rangeStart.begin());
  vtkTetMeshBuildState::ForBlocks(n, ranges,
    [&](int r, vtkIdType begin, vtkIdType end)
    {
      uint64_t running = rangeStart[r];
      for (vtkIdType v = begin; v < end; ++v)
      {
        start[v] = running;
        for (int b = 0; b < blocks; ++b)
        {
          // Absolute positions: 4 * 2^30 faces at most, so they fit 32 bits.
          uint32_t& c = counts[static_cast<size_t>(b) * numPoints + v];
          const uint32_t count = c;
          c = static_cast<uint32_t>(running);
          running += count;
        }
      }
    });
  start[numPoints] = rangeStart[ranges];
  return rangeStart[ranges];
}

//------------------------------------------------------------------------------
// Each of the `buckets` buckets of the last BucketFaces() paired on its own, in parallel; the
// non-manifold faces counted and the tetrahedra the overlap rule leaves out gathered in
// `result` (left out once every pass is done).
void vtkTetMeshFaceMatching::PairFaces(vtkTetMeshBuildState& state, size_t buckets, Pairing& result)
{
  vtkTetMesh* mesh = state.Mesh;
  FaceEntry* entries = state.FaceEntries.data();
  const uint64_t* start = state.BucketStarts.data();
  BucketPairing pairing;
  pairing.Neighbors = mesh->TetNeighbors.data();
  pairing.Sides = state.FaceSides.data();
  pairing.Flags = mesh->TetFlags.data();
  pairing.InputCells = mesh->TetInputCellIds.data();

  std::atomic<vtkIdType> nonManifold(0);
  std::mutex leftOutMutex;
  vtkSMPTools::For(0, static_cast<vtkIdType>(buckets), 2048,
    [&](vtkIdType vb, vtkIdType ve)
    {
      BucketPairing local = pairing;
      vtkIdType localNonManifold = 0;
      std::vector<vtkTetMeshOverlapRule::Entry> rule;
      std::vector<uint32_t> localLeftOut;
      std::vector<uint32_t> table;
      for (vtkIdType v = vb; v < ve; ++v)
      {
        FaceEntry* first = entries + start[v];
        FaceEntry* last = entries + start[v + 1];
        if (last - first >= 2 && !local.PairByTable(first, last, table))
        {
          localNonManifold += local.PairSorted(first, last, rule, localLeftOut);
        }
      }
      nonManifold += localNonManifold;
      if (!localLeftOut.empty())
      {
        std::lock_guard<std::mutex> lock(leftOutMutex);
        result.LeftOut.insert(result.LeftOut.end(), localLeftOut.begin(), localLeftOut.end());
      }
    });
  result.NonManifold += nonManifold;
}

//------------------------------------------------------------------------------
void vtkTetMeshFaceMatching::CollectBoundaryFaces(vtkTetMeshBuildState& state)
{
  vtkTetMesh* mesh = state.Mesh;
  const vtkIdType numFaces = 4 * mesh->GetNumberOfTetrahedra();
  const uint32_t* neighbors = mesh->TetNeighbors.data();
  const uint8_t* flags = mesh->TetFlags.data();
  // Faces of tetrahedra left out (vtkTetMeshOverlapRule) are no boundary: they are never entered.
  auto boundary = [neighbors, flags](vtkIdType f)
  { return neighbors[f] == NoNeighbor && !(flags[f >> 2] & vtkTetMesh::Overlapping); };
  const int blocks = vtkTetMeshBuildState::NumberOfBlocks(numFaces);
  std::vector<size_t> counts(static_cast<size_t>(blocks) + 1, 0);
  vtkTetMeshBuildState::ForBlocks(numFaces, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      size_t n = 0;
      for (vtkIdType f = begin; f < end; ++f)
      {
        n += boundary(f) ? 1 : 0;
      }
      counts[b + 1] = n;
    });
  std::partial_sum(counts.begin(), counts.end(), counts.begin());
  mesh->BoundaryFaces.resize(counts[blocks]);
  uint32_t* out = mesh->BoundaryFaces.data();
  vtkTetMeshBuildState::ForBlocks(numFaces, blocks,
    [&](int b, vtkIdType begin, vtkIdType end)
    {
      size_t pos = counts[b];
      for (vtkIdType f = begin; f < end; ++f)
      {
        if (boundary(f))
        {
          out[pos++] = static_cast<uint32_t>(f);
        }
      }
    });
}
