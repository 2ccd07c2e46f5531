/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastTestCheck.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// TRC_CHECK(cond): the test fails (returns EXIT_FAILURE) with file, line and condition when
// cond is false. Shared by the tests' utility headers.
#ifndef TiledRayCastTestCheck_h
#define TiledRayCastTestCheck_h

#include <cstdlib>
#include <iostream>

#define TRC_CHECK(cond)                                                                            \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond << std::endl;           \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

#endif
