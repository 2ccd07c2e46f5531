/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeSubProxyOverride.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeSubProxyOverride.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPVSessionBase.h"
#include "vtkPVXMLElement.h"
#include "vtkProcessModule.h"
#include "vtkSIProxyDefinitionManager.h"
#include "vtkSessionIterator.h"
#include "vtkSmartPointer.h"

#include <cstring>
#include <vector>

namespace
{
// The definition the plugin's XML extends, the subproxy it overrides, and its own proxy (the
// names of TiledRayCastRepresentation.xml).
constexpr const char* RepresentationGroup = "representations";
constexpr const char* CompositeRepresentation = "UnstructuredGridRepresentation";
constexpr const char* VolumeSubProxy = "VolumeRepresentation";
constexpr const char* PluginVolumeProxy = "TiledRayCastUnstructuredGridVolumeRepresentation";

bool Equal(const char* a, const char* b)
{
  return a && b && std::strcmp(a, b) == 0;
}

// The <Proxy> element of a <SubProxy> element named VolumeRepresentation, or null.
vtkPVXMLElement* VolumeProxyElement(vtkPVXMLElement* element)
{
  if (!Equal(element->GetName(), "SubProxy"))
  {
    return nullptr;
  }
  vtkPVXMLElement* proxy = element->FindNestedElementByName("Proxy");
  return proxy && Equal(proxy->GetAttribute("name"), VolumeSubProxy) ? proxy : nullptr;
}

// A definition manager registered (or replaced) a definition: when it is the composite
// representation's, the plugin's subproxy may have just been appended to it.
void OnDefinitionRegistered(vtkObject* caller, unsigned long, void*, void* callData)
{
  auto* info = static_cast<vtkSIProxyDefinitionManager::RegisteredDefinitionInformation*>(callData);
  if (info && !info->CustomDefinition && Equal(info->GroupName, RepresentationGroup) &&
    Equal(info->ProxyName, CompositeRepresentation))
  {
    vtkTiledRayCastVolumeSubProxyOverride::RemoveSupersededSubProxies(
      vtkSIProxyDefinitionManager::SafeDownCast(caller));
  }
}

vtkCallbackCommand* DefinitionObserver()
{
  static vtkSmartPointer<vtkCallbackCommand> observer;
  if (!observer)
  {
    observer = vtkSmartPointer<vtkCallbackCommand>::New();
    observer->SetCallback(OnDefinitionRegistered);
  }
  return observer;
}

// Watches one session's definition manager (once) and applies the override to what it holds.
void WatchSession(vtkSession* session)
{
  auto* pvSession = vtkPVSessionBase::SafeDownCast(session);
  vtkSIProxyDefinitionManager* manager =
    pvSession ? pvSession->GetProxyDefinitionManager() : nullptr;
  if (!manager)
  {
    return;
  }
  if (!manager->HasObserver(vtkCommand::RegisterEvent, DefinitionObserver()))
  {
    manager->AddObserver(vtkCommand::RegisterEvent, DefinitionObserver());
  }
  vtkTiledRayCastVolumeSubProxyOverride::RemoveSupersededSubProxies(manager);
}

// The process module registered a session (the GUI connecting, a client or server starting).
void OnSessionCreated(vtkObject* caller, unsigned long, void*, void* callData)
{
  auto* processModule = vtkProcessModule::SafeDownCast(caller);
  if (processModule && callData)
  {
    WatchSession(processModule->GetSession(*static_cast<vtkIdType*>(callData)));
  }
}
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeSubProxyOverride::Install()
{
  vtkProcessModule* processModule = vtkProcessModule::GetProcessModule();
  if (!processModule)
  {
    return;
  }
  static bool installed = false;
  if (!installed)
  {
    installed = true;
    vtkNew<vtkCallbackCommand> sessionObserver;
    sessionObserver->SetCallback(OnSessionCreated);
    processModule->AddObserver(vtkCommand::ConnectionCreatedEvent, sessionObserver);
  }
  vtkSmartPointer<vtkSessionIterator> sessions;
  sessions.TakeReference(processModule->NewSessionIterator());
  for (sessions->InitTraversal(); !sessions->IsDoneWithTraversal(); sessions->GoToNextItem())
  {
    WatchSession(sessions->GetCurrentSession());
  }
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeSubProxyOverride::RemoveSupersededSubProxies(
  vtkSIProxyDefinitionManager* manager)
{
  vtkPVXMLElement* definition = manager
    ? manager->GetProxyDefinition(RepresentationGroup, CompositeRepresentation, false)
    : nullptr;
  if (!definition)
  {
    return 0;
  }
  // ParaView's subproxy, and any other extension's that the plugin's replaces, come first;
  // the plugin's comes last (extensions are appended in the order plugins are loaded). Those
  // after the plugin's, if another plugin overrides it in turn, are left as they are.
  std::vector<vtkPVXMLElement*> superseded;
  bool pluginSubProxyFound = false;
  for (unsigned int i = 0; i < definition->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* element = definition->GetNestedElement(i);
    vtkPVXMLElement* proxy = VolumeProxyElement(element);
    if (!proxy)
    {
      continue;
    }
    if (Equal(proxy->GetAttribute("proxyname"), PluginVolumeProxy))
    {
      pluginSubProxyFound = true;
      break;
    }
    superseded.push_back(element);
  }
  if (!pluginSubProxyFound)
  {
    return 0;
  }
  for (vtkPVXMLElement* element : superseded)
  {
    definition->RemoveNestedElement(element);
  }
  return static_cast<int>(superseded.size());
}
