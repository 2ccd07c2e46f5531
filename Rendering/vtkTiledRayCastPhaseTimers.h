/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPhaseTimers.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastPhaseTimers
 * @brief   the GPU timers of a frame's phases (first hit, peeling, ray casting, compositing, total)
 *
 * A phase may run in several pieces (ray casting and peeling interleave): each piece has a
 * vtkOpenGLRenderTimer, and the phase's time is their sum. A frame is timed only when the
 * timers of the frame before have been read (BeginFrame): timers still in flight are not
 * restarted, and the statistics then keep the latest times measured. Read() never waits unless
 * asked to (SynchronousStatistics).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastPhaseTimers_h
#define vtkTiledRayCastPhaseTimers_h

#include <cstddef> // For size_t
#include <memory>  // For std::unique_ptr
#include <vector>  // For std::vector

class vtkOpenGLRenderTimer;
class vtkTiledRayCastStatistics;

class vtkTiledRayCastPhaseTimers
{
public:
  vtkTiledRayCastPhaseTimers();
  ~vtkTiledRayCastPhaseTimers();

  // GPU phases timed separately, and the whole frame.
  enum Phase
  {
    FirstHit = 0,
    Peeling,
    RayCasting,
    Compositing,
    Total,
    NumberOfPhases
  };

  /**
   * Starts a frame: true (and every phase reset) when it is timed, false while the timers of
   * an earlier frame are still in flight.
   */
  bool BeginFrame();

  ///@{
  /**
   * A piece of a phase, on frames that are timed (nothing otherwise).
   */
  void Start(Phase phase);
  void Stop(Phase phase);
  ///@}

  /**
   * Ends the frame: its timers, if it was timed, are now in flight.
   */
  void EndFrame() { this->Pending = this->Timing; }

  /**
   * Puts the times of the frame in flight in the statistics once they have arrived (at once,
   * waiting for the GPU, when `wait`). True when it did.
   */
  bool Read(bool wait, vtkTiledRayCastStatistics* stats);

  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastPhaseTimers(const vtkTiledRayCastPhaseTimers&) = delete;
  void operator=(const vtkTiledRayCastPhaseTimers&) = delete;

  // The pieces of one phase.
  struct Segments
  {
    std::vector<std::unique_ptr<vtkOpenGLRenderTimer>> Timers;
    size_t Used = 0;
    bool Ready() const;
    // Zero for pieces whose results are not there yet (vtkOpenGLRenderTimer does not wait).
    double GetMilliseconds() const;
  };
  bool Ready() const;

  Segments Phases[NumberOfPhases];
  bool Pending = false;
  bool Timing = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastPhaseTimers.h
