/*=========================================================================

  Program:   TiledRayCast
  Module:    BenchmarkUpload.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// How fast a mesh's arrays reach GPU memory, and what each way of sending them leaves in host
// memory (docs/benchmarks.md, "Upload"). The mapper's first frame of a billion tetrahedra sends
// 35 GB; VTK 9.1's vtkOpenGLBufferObject::Upload (glBufferData from the array) is one thread's
// copy through the driver, and NVIDIA's driver was seen to keep a host copy as large as the
// mesh. Each way sends the same array into fresh buffers of `--buffer-mib` each and is timed to
// its glFinish; the host's resident memory is read before, after, and once the buffers are gone:
//   vtk       vtkOpenGLBufferObject::Upload, what the mapper did
//   storage   glBufferStorage with the data, immutable, no client access
//   subdata   glBufferStorage empty, then glBufferSubData in chunks of `--chunk-mib`
//   staged    glBufferStorage empty; chunks copied by every core into persistently mapped host
//             buffers (three, used in turn behind fences) and copied on the GPU
//             (glCopyBufferSubData)
//   staged-mutable  the same into buffers made by glBufferData without data (as VTK 9.1's
//             vtkOpenGLBufferObject can later re-upload into)
//   mapped    glBufferStorage empty and mappable; mapped for writing, filled by every core
// Usage: BenchmarkUpload [--gib G] [--buffer-mib M] [--chunk-mib C] [--csv FILE] [WAY...]
#include "ProcessMemory.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkTypeUInt32Array.h"
#include "vtk_glew.h"

#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Every core copies its part of [source, source + bytes) to destination.
void ParallelCopy(void* destination, const void* source, size_t bytes)
{
  const size_t blocks = 64;
  const size_t block = (bytes + blocks - 1) / blocks;
  vtkSMPTools::For(0, static_cast<vtkIdType>(blocks), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        const size_t first = static_cast<size_t>(b) * block;
        if (first < bytes)
        {
          std::memcpy(static_cast<char*>(destination) + first,
            static_cast<const char*>(source) + first, std::min(block, bytes - first));
        }
      }
    });
}

GLint FreeVideoMemoryKiB()
{
  GLint kib = -1;
  while (glGetError() != GL_NO_ERROR)
  {
  }
  glGetIntegerv(0x9049, &kib); // GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
  return glGetError() == GL_NO_ERROR ? kib : -1;
}

struct Way
{
  std::string Name;
  size_t BufferBytes = 0;
  size_t ChunkBytes = 0;
  std::vector<vtkOpenGLBufferObject*> VTKBuffers;
  std::vector<GLuint> Buffers;

  // Sends bytes [first, first + count) of data into buffer k.
  void Send(size_t k, const char* data, size_t count)
  {
    if (this->Name == "vtk")
    {
      vtkOpenGLBufferObject* buffer = vtkOpenGLBufferObject::New();
      buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
      buffer->Upload(reinterpret_cast<const vtkTypeUInt32*>(data), count / 4,
        vtkOpenGLBufferObject::TextureBuffer);
      this->VTKBuffers.push_back(buffer);
      return;
    }
    GLuint handle = 0;
    glGenBuffers(1, &handle);
    this->Buffers.push_back(handle);
    glBindBuffer(GL_COPY_WRITE_BUFFER, handle);
    if (this->Name == "storage")
    {
      glBufferStorage(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(count), data, 0);
    }
    else if (this->Name == "subdata")
    {
      glBufferStorage(
        GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(count), nullptr, GL_DYNAMIC_STORAGE_BIT);
      for (size_t offset = 0; offset < count; offset += this->ChunkBytes)
      {
        glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset),
          static_cast<GLsizeiptr>(std::min(this->ChunkBytes, count - offset)), data + offset);
      }
    }
    else if (this->Name == "mapped")
    {
      glBufferStorage(
        GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(count), nullptr, GL_MAP_WRITE_BIT);
      void* target = glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(count),
        GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
      if (target)
      {
        ParallelCopy(target, data, count);
        glUnmapBuffer(GL_COPY_WRITE_BUFFER);
      }
      else
      {
        std::cerr << "mapped: glMapBufferRange failed\n";
      }
    }
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  }

  // The staged way: all buffers through three mapped host buffers of ChunkBytes.
  void SendStaged(const char* data, size_t bytes, bool mutableStorage)
  {
    const int slots = 3;
    GLuint staging[slots];
    void* mapped[slots];
    GLsync fences[slots] = { nullptr, nullptr, nullptr };
    glGenBuffers(slots, staging);
    const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    for (int s = 0; s < slots; ++s)
    {
      glBindBuffer(GL_COPY_READ_BUFFER, staging[s]);
      glBufferStorage(GL_COPY_READ_BUFFER, static_cast<GLsizeiptr>(this->ChunkBytes), nullptr,
        flags | GL_CLIENT_STORAGE_BIT);
      mapped[s] =
        glMapBufferRange(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(this->ChunkBytes), flags);
    }
    int slot = 0;
    for (size_t first = 0; first < bytes; first += this->BufferBytes)
    {
      const size_t count = std::min(this->BufferBytes, bytes - first);
      GLuint handle = 0;
      glGenBuffers(1, &handle);
      this->Buffers.push_back(handle);
      glBindBuffer(GL_COPY_WRITE_BUFFER, handle);
      if (mutableStorage)
      {
        glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(count), nullptr, GL_STATIC_DRAW);
      }
      else
      {
        glBufferStorage(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(count), nullptr, 0);
      }
      for (size_t offset = 0; offset < count; offset += this->ChunkBytes)
      {
        const size_t piece = std::min(this->ChunkBytes, count - offset);
        if (fences[slot])
        {
          while (glClientWaitSync(fences[slot], GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000) ==
            GL_TIMEOUT_EXPIRED)
          {
          }
          glDeleteSync(fences[slot]);
        }
        ParallelCopy(mapped[slot], data + first + offset, piece);
        glBindBuffer(GL_COPY_READ_BUFFER, staging[slot]);
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0,
          static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(piece));
        fences[slot] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        slot = (slot + 1) % slots;
      }
    }
    glFinish();
    for (int s = 0; s < slots; ++s)
    {
      if (fences[s])
      {
        glDeleteSync(fences[s]);
      }
      glBindBuffer(GL_COPY_READ_BUFFER, staging[s]);
      glUnmapBuffer(GL_COPY_READ_BUFFER);
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    glDeleteBuffers(slots, staging);
  }

  void Release()
  {
    for (vtkOpenGLBufferObject* buffer : this->VTKBuffers)
    {
      buffer->ReleaseGraphicsResources();
      buffer->Delete();
    }
    this->VTKBuffers.clear();
    if (!this->Buffers.empty())
    {
      glDeleteBuffers(static_cast<GLsizei>(this->Buffers.size()), this->Buffers.data());
    }
    this->Buffers.clear();
    glFinish();
  }
};
}

int main(int argc, char* argv[])
{
  double gib = 8;
  size_t bufferMiB = 2048, chunkMiB = 128;
  std::string csv;
  std::vector<std::string> ways;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--gib" && i + 1 < argc)
    {
      gib = std::stod(argv[++i]);
    }
    else if (arg == "--buffer-mib" && i + 1 < argc)
    {
      bufferMiB = std::stoul(argv[++i]);
    }
    else if (arg == "--chunk-mib" && i + 1 < argc)
    {
      chunkMiB = std::stoul(argv[++i]);
    }
    else if (arg == "--csv" && i + 1 < argc)
    {
      csv = argv[++i];
    }
    else if (arg == "vtk" || arg == "storage" || arg == "subdata" || arg == "staged" ||
      arg == "staged-mutable" || arg == "mapped")
    {
      ways.push_back(arg);
    }
    else
    {
      std::cerr << "Usage: BenchmarkUpload [--gib G] [--buffer-mib M] [--chunk-mib C] [--csv "
                   "FILE] [vtk|storage|subdata|staged|staged-mutable|mapped]...\n";
      return 1;
    }
  }
  if (ways.empty())
  {
    ways = { "vtk", "storage", "subdata", "staged", "staged-mutable", "mapped" };
  }
  const size_t bytes = static_cast<size_t>(gib * 1024 * 1024 * 1024) / 16 * 16;
  const size_t bufferBytes = bufferMiB << 20;
  const size_t chunkBytes = chunkMiB << 20;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  window->SetOffScreenRendering(1);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  window->MakeCurrent();
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl || !gl->IsCurrent())
  {
    std::cerr << "No current OpenGL context\n";
    return 1;
  }
  std::cout << "OpenGL " << glGetString(GL_VERSION) << " on " << glGetString(GL_RENDERER) << "\n";

  vtkNew<vtkTypeUInt32Array> source;
  source->SetNumberOfValues(static_cast<vtkIdType>(bytes / 4));
  vtkTypeUInt32* values = source->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(bytes / 4),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        values[i] = static_cast<vtkTypeUInt32>(i * 2654435761u);
      }
    });
  const char* data = reinterpret_cast<const char*>(values);
  {
    // The host's own copy rate, for scale.
    std::vector<char> scratch(std::min<size_t>(bytes, size_t(1) << 30));
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    ParallelCopy(scratch.data(), data, scratch.size());
    timer->StopTimer();
    std::cout << "host copy, every core: " << scratch.size() / timer->GetElapsedTime() / 1e9
              << " GB/s\n";
  }

  std::ofstream out;
  if (!csv.empty())
  {
    out.open(csv);
    out << "way,bytes,buffer_bytes,chunk_bytes,threads,seconds,gb_per_s,host_rss_added_mb,"
           "host_rss_after_release_mb,gpu_used_mb\n";
  }
  for (const std::string& name : ways)
  {
    Way way;
    way.Name = name;
    way.BufferBytes = bufferBytes;
    way.ChunkBytes = chunkBytes;
    glFinish();
    const double rssBefore = trcbench::ProcessMemory("VmRSS");
    const GLint freeBefore = FreeVideoMemoryKiB();
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    if (name == "staged" || name == "staged-mutable")
    {
      way.SendStaged(data, bytes, name == "staged-mutable");
    }
    else
    {
      for (size_t first = 0, k = 0; first < bytes; first += bufferBytes, ++k)
      {
        way.Send(k, data + first, std::min(bufferBytes, bytes - first));
      }
    }
    glFinish();
    timer->StopTimer();
    const GLenum error = glGetError();
    const double rssAfter = trcbench::ProcessMemory("VmRSS");
    const GLint freeAfter = FreeVideoMemoryKiB();
    way.Release();
    const double rssReleased = trcbench::ProcessMemory("VmRSS");
    const double seconds = timer->GetElapsedTime();
    const double usedMiB =
      freeBefore >= 0 && freeAfter >= 0 ? (freeBefore - freeAfter) / 1024.0 : -1;
    std::cout << name << ": " << bytes / 1e9 << " GB in " << seconds << " s, "
              << bytes / seconds / 1e9 << " GB/s; host memory +" << (rssAfter - rssBefore) / 1e6
              << " MB after, +" << (rssReleased - rssBefore) / 1e6
              << " MB once released; GPU memory used " << usedMiB << " MiB"
              << (error != GL_NO_ERROR ? " (GL error " + std::to_string(error) + ")" : "") << "\n";
    if (out)
    {
      out << name << "," << bytes << "," << bufferBytes << "," << chunkBytes << ","
          << vtkSMPTools::GetEstimatedNumberOfThreads() << "," << seconds << ","
          << bytes / seconds / 1e9 << "," << (rssAfter - rssBefore) / 1e6 << ","
          << (rssReleased - rssBefore) / 1e6 << "," << usedMiB << "\n";
    }
  }
  return 0;
}
