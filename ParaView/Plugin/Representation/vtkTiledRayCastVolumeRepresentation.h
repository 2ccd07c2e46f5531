/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeRepresentation.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumeRepresentation
 * @brief   ParaView's Volume representation of unstructured grids, with "Tiled ray cast"
 *
 * ParaView 5.11 hard-codes the four volume mappers of its Volume representation of
 * unstructured grids (vtkSIUnstructuredGridVolumeRepresentationProxy registers them by name),
 * and its GUI and Python compare the representation's name "Volume" literally. So this
 * representation does not add a representation type: the plugin's XML overrides the existing
 * Volume representation with this subclass, which registers a vtkTiledRayCastVolumeMapper as a
 * fifth mapper, "Tiled ray cast", and exposes its settings as properties.
 *
 * ParaView forwards the colour map's VectorMode and VectorComponent only to its smart mappers;
 * this class forwards them to the tiled ray-cast mapper too, so that a vector array coloured by
 * magnitude or by a component renders what the colour legend says.
 */

#ifndef vtkTiledRayCastVolumeRepresentation_h
#define vtkTiledRayCastVolumeRepresentation_h

#include "vtkNew.h"                        // For vtkNew
#include "vtkParaViewTiledRayCastModule.h" // For export macro
#include "vtkTiledRayCastVolumeMapper.h"   // For vtkNew
#include "vtkUnstructuredGridVolumeRepresentation.h"

#include <string> // For std::string

class VTKPARAVIEWTILEDRAYCAST_EXPORT vtkTiledRayCastVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkTiledRayCastVolumeRepresentation* New();
  vtkTypeMacro(vtkTiledRayCastVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The name under which the mapper is offered in SelectMapper.
   */
  static const char* GetTiledRayCastMapperName() { return "Tiled ray cast"; }

  /**
   * Makes this class ParaView's Volume representation of unstructured grids in every proxy
   * definition manager of the process, without ParaView creating its own first and replacing it
   * (which makes ParaView 5.11 print twelve deprecation warnings per representation). The
   * plugin calls it when it is loaded; see vtkTiledRayCastVolumeSubProxyOverride.
   */
  static void InitializeProcess();

  ///@{
  /**
   * Settings of the tiled ray-cast mapper (see vtkTiledRayCastVolumeMapper): integration mode,
   * pipeline, tile size of the fragment pipeline, opacity at which rays stop, empty-space
   * skipping, the automatic integration's error budget.
   */
  void SetTiledRayCastIntegrationMode(int mode);
  int GetTiledRayCastIntegrationMode();
  void SetTiledRayCastPipeline(int pipeline);
  int GetTiledRayCastPipeline();
  void SetTiledRayCastTileSize(int size);
  int GetTiledRayCastTileSize();
  void SetTiledRayCastEarlyTerminationOpacity(double opacity);
  double GetTiledRayCastEarlyTerminationOpacity();
  void SetTiledRayCastEmptySpaceSkipping(int skipping);
  int GetTiledRayCastEmptySpaceSkipping();
  void SetTiledRayCastMaximumError(double error);
  double GetTiledRayCastMaximumError();
  ///@}

  ///@{
  /**
   * Whether ParaView cuts the cells that straddle the ranks' partition planes when it
   * redistributes the mesh for ordered compositing (default on, with the tiled ray-cast mapper
   * only): see ProcessViewRequest().
   */
  void SetTiledRayCastSplitBoundaryCells(int split);
  vtkGetMacro(TiledRayCastSplitBoundaryCells, int);
  ///@}

  /**
   * The mapper's statistics of its last frame (vtkTiledRayCastStatistics::GetSummary()), or an
   * empty string before its first frame. Read from Python through the information property
   * TiledRayCastStatistics.
   */
  const char* GetTiledRayCastStatistics();

  /**
   * Forwarded to vtkTiledRayCastVolumeMapper::SetSynchronousStatistics: every frame waits for
   * its GPU timers and counts, so that TiledRayCastStatistics describes that frame (for
   * measuring; off by default, as in the mapper).
   */
  void SetTiledRayCastSynchronousStatistics(int synchronous);
  int GetTiledRayCastSynchronousStatistics();

  /**
   * The mapper itself.
   */
  vtkTiledRayCastVolumeMapper* GetTiledRayCastMapper() { return this->TiledRayCastMapper; }

protected:
  vtkTiledRayCastVolumeRepresentation();
  ~vtkTiledRayCastVolumeRepresentation() override;

  void UpdateMapperParameters() override;

  /**
   * As ParaView's; under MPI, the cells of the piece ParaView will redistribute are then
   * copied into a fresh vtkCellArray. On three or more ranks, ParaView 5.11's redistribution
   * (vtkRedistributeDataSetFilter, through vtkExtractCells) corrupts memory and crashes on the
   * cell arrays of its XML readers' output (a .pvtu read piece by piece, with any of the Volume
   * representation's mappers, and with the RedistributeDataSet filter alone); a copy, which
   * holds the same cells, does not. Measured: 0 of 9 runs at 3-6 ranks ended before, all do now.
   */
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * As ParaView's, and with the tiled ray-cast mapper (and TiledRayCastSplitBoundaryCells on)
   * asks ParaView to split the cells that straddle the ranks' partition planes
   * (vtkRedistributeDataSetFilter's SPLIT_BOUNDARY_CELLS) instead of giving each to one rank:
   * every rank's piece then lies inside its own box of the partition, so the boxes' visibility
   * order is the order of the pieces along every ray and compositing the ranks' images is exact.
   * (ParaView's own mappers keep ParaView's choice, one rank per cell.)
   */
  int ProcessViewRequest(vtkInformationRequestKey* requestType, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  vtkNew<vtkTiledRayCastVolumeMapper> TiledRayCastMapper;
  std::string StatisticsSummary;
  int TiledRayCastSplitBoundaryCells = 1;

private:
  vtkTiledRayCastVolumeRepresentation(const vtkTiledRayCastVolumeRepresentation&) = delete;
  void operator=(const vtkTiledRayCastVolumeRepresentation&) = delete;
};

#endif
