/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastGroupTraversal.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastGroupTraversal.h"

#include "vtkShaderProgram.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtkTiledRayCastMemberUniforms.h"
#include "vtkTiledRayCastSharedMemberCode.h"

#include "vtkTiledRayCastEntryList.h"
#include "vtkTiledRayCastGroupMember.h"
#include "vtkTiledRayCastGroupTraversalCS.h"
#include "vtkTiledRayCastTraversalTile.h"
#include "vtkTiledRayCastVolumetricPeelRanges.h"
#include "vtkTiledRayCastWalk.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <sstream>

namespace
{
// The uniforms every volume of a group shares, declared once: the scene's depth, and the partial
// pre-integration table (the same function whatever the transfer function).
const char* const SharedUniforms[] = { "in_opaqueDepth", "in_psiTable", "in_psiTableSize" };

bool IsShared(const std::string& word)
{
  return std::find(std::begin(SharedUniforms), std::end(SharedUniforms), word) !=
    std::end(SharedUniforms);
}

// The identifiers of one volume's code: its functions and types (trc*, Trc*), constants and
// switches (TRC_*) and uniforms (in_*), but the shared uniforms.
bool IsVolumeIdentifier(const std::string& word)
{
  auto starts = [&word](const char* prefix)
  { return word.compare(0, std::char_traits<char>::length(prefix), prefix) == 0; };
  return (starts("trc") || starts("Trc") || starts("TRC_") || starts("in_")) && !IsShared(word);
}

// `code` without its declarations of the shared uniforms (the first volume's code holds them).
std::string WithoutSharedDeclarations(const std::string& code)
{
  std::istringstream in(code);
  std::string out;
  std::string line;
  while (std::getline(in, line))
  {
    bool shared = false;
    for (const char* name : SharedUniforms)
    {
      const std::string declared = std::string(" ") + name + ";";
      shared = shared ||
        (line.compare(0, 8, "uniform ") == 0 && line.size() >= declared.size() &&
          line.compare(line.size() - declared.size(), declared.size(), declared) == 0);
    }
    if (!shared)
    {
      out += line + "\n";
    }
  }
  return out;
}
} // anonymous namespace

//------------------------------------------------------------------------------
vtkTiledRayCastGroupTraversal::vtkTiledRayCastGroupTraversal() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastGroupTraversal::~vtkTiledRayCastGroupTraversal() = default;

//------------------------------------------------------------------------------
std::string vtkTiledRayCastGroupTraversal::Rename(
  const std::string& code, const std::string& suffix)
{
  std::string out;
  out.reserve(code.size() + code.size() / 8);
  size_t i = 0;
  while (i < code.size())
  {
    const char c = code[i];
    if (std::isdigit(static_cast<unsigned char>(c)))
    {
      // A number (1e-12, 0x7FFFFFFFu): copied whole, so that no part of it reads as a name.
      size_t j = i;
      while (j < code.size() &&
        (vtkTiledRayCastSharedMemberCode::IsIdentifierChar(code[j]) || code[j] == '.'))
      {
        ++j;
      }
      out.append(code, i, j - i);
      i = j;
    }
    else if (vtkTiledRayCastSharedMemberCode::IsIdentifierChar(c))
    {
      size_t j = i;
      while (j < code.size() && vtkTiledRayCastSharedMemberCode::IsIdentifierChar(code[j]))
      {
        ++j;
      }
      const std::string word = code.substr(i, j - i);
      out += word;
      if (IsVolumeIdentifier(word))
      {
        out += suffix;
      }
      i = j;
    }
    else
    {
      out += c;
      ++i;
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::string vtkTiledRayCastGroupTraversal::Expand(const std::string& code, int count)
{
  const std::string tag = "//TRC::EachMember ";
  std::istringstream in(code);
  std::string out;
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, tag.size(), tag) != 0)
    {
      out += line + "\n";
      continue;
    }
    const std::string body = line.substr(tag.size());
    for (int k = 0; k < count; ++k)
    {
      std::string copy = body;
      for (size_t at = copy.find('@'); at != std::string::npos; at = copy.find('@', at))
      {
        copy.replace(at, 1, std::to_string(k));
      }
      out += "  " + copy + "\n";
    }
  }
  return out;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastGroupTraversal::Update(const std::vector<Inputs>& inputs,
  const std::vector<Replacements>& members, const std::string& version, std::string& error)
{
  this->Composition.Reset();
  const int count = static_cast<int>(members.size());
  if (count < 1 || count > MaximumMembers)
  {
    error = "The traversal of overlapping volumes takes 1 to " + std::to_string(MaximumMembers) +
      " volumes.";
    return false;
  }
  // Each volume's code: what its own traversal holds, then what the group needs of it.
  std::vector<std::string> codes;
  for (int k = 0; k < count; ++k)
  {
    std::string code;
    for (const char* tag :
      { "//TRC::Common::Dec", "//TRC::Layout::Dec", "//TRC::Integration::Dec" })
    {
      for (const auto& r : members[k])
      {
        if (r.first == tag)
        {
          code += r.second + "\n";
        }
      }
    }
    code += vtkTiledRayCastWalk;
    code += vtkTiledRayCastGroupMember;
    codes.push_back(code);
  }
  // Volumes of the same code share one copy of it where it can be shared; else each has its own,
  // renamed.
  std::string volumes;
  std::string why; // what Make() could not share (for a debugger: either way the group is drawn)
  this->Indexed.clear();
  this->SharedCode = count >= SharedCodeMembers &&
    std::all_of(
      codes.begin(), codes.end(), [&codes](const std::string& c) { return c == codes[0]; }) &&
    vtkTiledRayCastSharedMemberCode::Make(codes[0], count,
      std::vector<std::string>(std::begin(SharedUniforms), std::end(SharedUniforms)), volumes,
      this->Indexed, why);
  if (!this->SharedCode)
  {
    volumes.clear();
    this->Indexed.clear();
  }
  for (int k = 0; !this->SharedCode && k < count; ++k)
  {
    const std::string code = k > 0 ? WithoutSharedDeclarations(codes[k]) : codes[k];
    volumes += "// Volume " + std::to_string(k) + "\n" + Rename(code, "_v" + std::to_string(k));
  }
  std::string source = Expand(vtkTiledRayCastGroupTraversalCS, count);
  vtkShaderProgram::Substitute(source, "//TRC::Group::Members", volumes, false);
  vtkShaderProgram::Substitute(source, "//TRC::EntryList::Dec", vtkTiledRayCastEntryList, false);
  vtkShaderProgram::Substitute(
    source, "//TRC::TraversalTile::Dec", vtkTiledRayCastTraversalTile, false);
  this->Source = source;
  this->Version = version + "#define TRC_GROUP_MEMBERS " + std::to_string(count) + "\n";
  this->NumberOfMembers = count;
  for (StageProgram& stage : this->Stages)
  {
    stage.Built = false;
  }
  this->Composition.Built(inputs);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastGroupTraversal::Prepare(int stage, std::string& error)
{
  if (stage < 0 || stage >= NumberOfStages || this->NumberOfMembers == 0)
  {
    error = "The traversal of overlapping volumes has no program for this stage.";
    return false;
  }
  StageProgram& built = this->Stages[stage];
  if (built.Built)
  {
    return true;
  }
  // Inside VTK's depth peeling: the stage's ranges (vtkTiledRayCastVolumetricPeelRanges.glsl).
  std::string source = this->Source;
  vtkShaderProgram::Substitute(source, "//TRC::Version",
    stage > 0 ? this->Version + "#define TRC_PEEL_STAGE " + std::to_string(stage) + "\n"
              : this->Version,
    false);
  vtkShaderProgram::Substitute(source, "//TRC::VolumetricPeel::Dec",
    stage > 0 ? vtkTiledRayCastVolumetricPeelRanges : "", false);
  vtkTiledRayCastComputeShader* program = built.Program;
  if ((source != program->GetSource() || !program->GetHandle()) && !program->Build(source))
  {
    error = "The compute shader of the tiled ray caster's traversal of overlapping volumes failed "
            "to build (" +
      program->GetError() + ").";
    this->Invalidate();
    return false;
  }
  for (int k = 0; k < MaximumMembers; ++k)
  {
    if (k < this->NumberOfMembers)
    {
      // The first volume sets the partial pre-integration table they share; the caller the
      // scene's depth.
      const std::vector<std::string> psi = { "in_psiTable", "in_psiTableSize" };
      std::vector<std::string> shared = { "in_opaqueDepth" };
      if (k > 0)
      {
        shared.insert(shared.end(), psi.begin(), psi.end());
      }
      built.Members[k]->Map(program, "_v" + std::to_string(k), shared,
        k == 0 ? psi : std::vector<std::string>(), this->Indexed, k);
    }
    else
    {
      built.Members[k]->Unmap();
    }
  }
  built.Built = true;
  return true;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastGroupTraversal::GetTextureUnits(const Inputs& inputs)
{
  // Tet points and neighbours, points, cell scalars (texture buffers, each array split over as
  // many as it needs), the transfer function and the visible tets.
  return 2 * inputs.TetTextureBuffers + inputs.PointTextureBuffers +
    (inputs.CellScalars ? inputs.TetTextureBuffers : 0) + 1 + (inputs.SkipEmptySpace ? 1 : 0);
}

//------------------------------------------------------------------------------
int vtkTiledRayCastGroupTraversal::GetSharedTextureUnits(int stage)
{
  // The scene's depth and the partial pre-integration table; VTK's depth peeling's textures at
  // each stage (vtkTiledRayCastVolumetricPeelRanges.glsl).
  const int peel[4] = { 0, 2, 3, 1 };
  return 2 + (stage >= 0 && stage < 4 ? peel[stage] : 0);
}

//------------------------------------------------------------------------------
vtkTiledRayCastComputeShader* vtkTiledRayCastGroupTraversal::GetProgram(int stage)
{
  return this->Stages[stage].Program;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkTiledRayCastGroupTraversal::Member(int stage, int k)
{
  return this->Stages[stage].Members[k];
}

//------------------------------------------------------------------------------
void vtkTiledRayCastGroupTraversal::ReleaseGraphicsResources()
{
  for (StageProgram& stage : this->Stages)
  {
    for (auto& member : stage.Members)
    {
      member->Unmap();
    }
    stage.Program->ReleaseProgram();
    stage.Built = false;
  }
  this->NumberOfMembers = 0;
  this->SharedCode = false;
  this->Indexed.clear();
  this->Source.clear();
  this->Composition.Reset();
}
