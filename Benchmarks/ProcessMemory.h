/*=========================================================================

  Program:   TiledRayCast
  Module:    ProcessMemory.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The benchmarks' view of their own host memory (Linux): a field of /proc/self/status in bytes
// (VmRSS, the resident memory now; VmHWM, its peak) and resetting the peak to the resident
// memory now (/proc/self/clear_refs, Linux 4.0 and later), so that a peak can be taken over one
// step of a program.
#ifndef ProcessMemory_h
#define ProcessMemory_h

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace trcbench
{
// The field's value in bytes ("VmHWM:  123456 kB"), or NaN where there is none.
inline double ProcessMemory(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const size_t length = std::strlen(field);
  while (std::getline(status, line))
  {
    if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':')
    {
      return 1024.0 * std::atof(line.c_str() + length + 1);
    }
  }
  return NAN;
}

// Resets the peak (VmHWM) to the resident memory now; false where the kernel cannot (then the
// peak is the process's whole peak).
inline bool ResetPeakMemory()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return clear.good();
}
} // namespace trcbench

#endif
