/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastSharedMemberCode.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastSharedMemberCode.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <sstream>

namespace
{
// The reads of a sampler type that go through a volume's function: the read's name and the
// parameters after the sampler, by the sampler's dimensions. Empty for a type not handled.
std::vector<std::pair<std::string, std::string>> Reads(const std::string& type)
{
  const auto ends = [&type](const std::string& tail)
  {
    return type.size() >= tail.size() &&
      type.compare(type.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (ends("samplerBuffer"))
  {
    return { { "texelFetch", "int p" } };
  }
  const char* coordinates[3][2] = { { "int", "float" }, { "ivec2", "vec2" }, { "ivec3", "vec3" } };
  for (int d = 0; d < 3; ++d)
  {
    if (ends("sampler" + std::to_string(d + 1) + "D"))
    {
      return { { "texelFetch", std::string(coordinates[d][0]) + " p, int lod" },
        { "texture", std::string(coordinates[d][1]) + " p" },
        { "textureLod", std::string(coordinates[d][1]) + " p, float lod" } };
    }
  }
  return {};
}

std::string DispatcherName(const std::string& read, const std::string& sampler)
{
  std::string name = read;
  name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return "trcGroup" + name + "_" + sampler;
}

// The names of `parameters` ("ivec2 p, int lod" gives "p, lod").
std::string Arguments(const std::string& parameters)
{
  std::string out;
  std::istringstream in(parameters);
  std::string piece;
  while (std::getline(in, piece, ','))
  {
    const size_t space = piece.find_last_of(' ');
    out += (out.empty() ? "" : ", ") + piece.substr(space + 1);
  }
  return out;
}

// Volume k's samplers, and for each read a function that reads the sampler of the volume whose
// code runs: a branch per volume around the read alone.
std::string SamplerDeclarations(const std::string& type, const std::string& name, int count)
{
  std::string code;
  for (int k = 0; k < count; ++k)
  {
    code += "uniform " + type + " " + name + vtkTiledRayCastSharedMemberCode::Suffix(k) + ";\n";
  }
  const std::string texel = type[0] == 'u' ? "uvec4" : (type[0] == 'i' ? "ivec4" : "vec4");
  for (const auto& read : Reads(type))
  {
    const std::string arguments = Arguments(read.second);
    code += texel + " " + DispatcherName(read.first, name) + "(" + read.second + ")\n{\n";
    for (int k = count - 1; k > 0; --k)
    {
      code += "  if (trcMemberIndex == " + std::to_string(k) + ")\n  {\n    return " + read.first +
        "(" + name + vtkTiledRayCastSharedMemberCode::Suffix(k) + ", " + arguments + ");\n  }\n";
    }
    code += "  return " + read.first + "(" + name + vtkTiledRayCastSharedMemberCode::Suffix(0) +
      ", " + arguments + ");\n}\n";
  }
  return code;
}

// The end of `out` without trailing blanks is "<read>(" for one of `reads`: that read, else "".
std::string ReadBefore(
  std::string& out, const std::vector<std::pair<std::string, std::string>>& reads)
{
  size_t end = out.find_last_not_of(" \t");
  if (end == std::string::npos || out[end] != '(')
  {
    return std::string();
  }
  size_t nameEnd = out.find_last_not_of(" \t", end - 1);
  if (nameEnd == std::string::npos)
  {
    return std::string();
  }
  size_t nameBegin = nameEnd;
  while (nameBegin > 0 && vtkTiledRayCastSharedMemberCode::IsIdentifierChar(out[nameBegin - 1]))
  {
    --nameBegin;
  }
  const std::string word = out.substr(nameBegin, nameEnd + 1 - nameBegin);
  for (const auto& read : reads)
  {
    if (read.first == word)
    {
      out.resize(nameBegin);
      return word;
    }
  }
  return std::string();
}
} // anonymous namespace

//------------------------------------------------------------------------------
bool vtkTiledRayCastSharedMemberCode::Make(const std::string& code, int count,
  const std::vector<std::string>& sharedUniforms, std::string& shared,
  std::vector<std::string>& indexed, std::string& why)
{
  shared.clear();
  indexed.clear();
  // Pass 1: the declarations of the volume's own uniforms.
  static const std::regex declaration(R"(^\s*uniform\s+(\w+)\s+(in_\w+)\s*(\[[^\]]*\])?\s*;(.*)$)");
  std::map<std::string, std::string> samplers; // name -> type
  std::vector<std::string> lines;
  {
    std::istringstream in(code);
    std::string line;
    while (std::getline(in, line))
    {
      lines.push_back(line);
    }
  }
  std::vector<std::string> replaced(lines.size());
  std::vector<bool> isDeclaration(lines.size(), false);
  for (size_t i = 0; i < lines.size(); ++i)
  {
    std::smatch match;
    if (!std::regex_match(lines[i], match, declaration))
    {
      // A uniform of the volume's declared otherwise (a layout qualifier, several names) would
      // be shared by every volume unseen: refused, the volumes keep a copy each.
      static const std::regex other(R"(^\s*(layout\s*\(.*\)\s*)?uniform\b.*\bin_\w+)");
      if (std::regex_search(lines[i], other))
      {
        bool sharedOnly = false;
        for (const std::string& name : sharedUniforms)
        {
          sharedOnly = sharedOnly || lines[i].find(name) != std::string::npos;
        }
        if (!sharedOnly)
        {
          why = "a uniform declaration it does not read (\"" + lines[i] + "\")";
          return false;
        }
      }
      continue;
    }
    const std::string type = match[1];
    const std::string name = match[2];
    if (std::find(sharedUniforms.begin(), sharedUniforms.end(), name) != sharedUniforms.end())
    {
      continue;
    }
    isDeclaration[i] = true;
    if (type.find("sampler") != std::string::npos || type.find("image") != std::string::npos)
    {
      if (Reads(type).empty())
      {
        why = "uniform " + name + " (" + type + ") is not a sampler it can choose per volume";
        return false;
      }
      samplers[name] = type;
      replaced[i] = SamplerDeclarations(type, name, count);
    }
    else
    {
      indexed.push_back(name);
      replaced[i] = "uniform " + type + " " + name + "[TRC_GROUP_MEMBERS]" + match[3].str() + ";" +
        match[4].str() + "\n";
    }
  }
  // Pass 2: every use of them, outside comments.
  shared = "#define TRC_GROUP_SHARED_CODE\n"
           "// The volume whose code runs: it picks the volume's uniforms and samplers.\n"
           "int trcMemberIndex = 0;\n";
  bool inBlockComment = false;
  for (size_t l = 0; l < lines.size(); ++l)
  {
    if (isDeclaration[l])
    {
      shared += replaced[l];
      continue;
    }
    const std::string& text = lines[l];
    std::string out;
    size_t i = 0;
    while (i < text.size())
    {
      if (inBlockComment)
      {
        const size_t close = text.find("*/", i);
        const size_t end = close == std::string::npos ? text.size() : close + 2;
        out.append(text, i, end - i);
        inBlockComment = close == std::string::npos;
        i = end;
        continue;
      }
      if (text.compare(i, 2, "//") == 0)
      {
        out.append(text, i, std::string::npos);
        break;
      }
      if (text.compare(i, 2, "/*") == 0)
      {
        out += "/*";
        i += 2;
        inBlockComment = true;
        continue;
      }
      const char c = text[i];
      if (!IsIdentifierChar(c))
      {
        out += c;
        ++i;
        continue;
      }
      size_t j = i;
      const bool number = std::isdigit(static_cast<unsigned char>(c)) != 0;
      while (j < text.size() && (IsIdentifierChar(text[j]) || (number && text[j] == '.')))
      {
        ++j;
      }
      const std::string word = text.substr(i, j - i);
      i = j;
      auto sampler = samplers.find(word);
      if (!number && sampler != samplers.end())
      {
        // Only as a read's first argument: the read becomes the volume's function.
        const std::string read = ReadBefore(out, Reads(sampler->second));
        size_t comma = text.find_first_not_of(" \t", i);
        if (read.empty() || comma == std::string::npos || text[comma] != ',')
        {
          why = word +
            " is used otherwise than as the sampler of texelFetch, texture or "
            "textureLod (line \"" +
            text + "\")";
          return false;
        }
        out += DispatcherName(read, word) + "(";
        i = comma + 1;
        continue;
      }
      out += word;
      if (!number && std::find(indexed.begin(), indexed.end(), word) != indexed.end())
      {
        out += "[trcMemberIndex]";
      }
    }
    shared += out + "\n";
  }
  return true;
}
