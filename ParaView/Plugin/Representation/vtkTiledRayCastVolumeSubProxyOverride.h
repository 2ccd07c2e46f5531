/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeSubProxyOverride.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumeSubProxyOverride
 * @brief   private: makes the plugin's Volume subproxy the only one in ParaView's definitions
 *
 * The plugin's XML extends ParaView's UnstructuredGridRepresentation with a second
 * "VolumeRepresentation" subproxy (override="1", our vtkTiledRayCastVolumeRepresentation). An
 * extension can only append to a definition, so as is, each representation proxy would create
 * ParaView's own Volume subproxy first and then replace it; and ParaView 5.11's
 * vtkSMProxy::RemoveSubProxy calls its own deprecated vtkSMProxyLink::GetNumberOfLinkedProxies()
 * for every shared-property link of the representation, which prints one warning each: twelve
 * per representation, opening the GUI's Output Messages window whenever data is shown.
 *
 * Install() removes the superseded subproxy from the definition itself, in every proxy
 * definition manager of the process: those of the sessions that exist (pvbatch, a server) and
 * of those created later (the GUI's), each time the definition is registered or replaced (the
 * plugin's XML being loaded, a client receiving its server's definitions). The representation
 * is then created once, as the plugin's, and nothing is removed or printed. The XML extension
 * stays the one description of the override: without Install() it would still work, with the
 * warnings.
 */

#ifndef vtkTiledRayCastVolumeSubProxyOverride_h
#define vtkTiledRayCastVolumeSubProxyOverride_h

class vtkSIProxyDefinitionManager;

class vtkTiledRayCastVolumeSubProxyOverride
{
public:
  /**
   * Applies the override to every definition manager of this process, now and whenever one
   * is created or its UnstructuredGridRepresentation definition registered. Called once per
   * process when the plugin is loaded; calling it again does nothing more.
   */
  static void Install();

  /**
   * Removes the subproxies named VolumeRepresentation that come before the plugin's in
   * `manager`'s UnstructuredGridRepresentation definition; returns how many it removed (0 when
   * the plugin's subproxy is not there yet, or nothing precedes it).
   */
  static int RemoveSupersededSubProxies(vtkSIProxyDefinitionManager* manager);
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastVolumeSubProxyOverride.h
