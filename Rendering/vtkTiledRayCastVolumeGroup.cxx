/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeGroup.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeGroup.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkTiledRayCastVolumeMapper.h"
#include "vtkTiledRayCastVolumeOrder.h"
#include "vtkTiledRayCastVolumetricPeel.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <map>
#include <set>

namespace
{
// Per renderer, the volumes drawn in its current frame by another volume's mapper. Cleared when
// the renderer starts a frame (its StartEvent comes before any volume is drawn), so a mark
// never outlives the frame it was made in, whatever order VTK calls the mappers in next.
struct RendererFrame
{
  vtkWeakPointer<vtkRenderer> Renderer;
  std::set<vtkVolume*> Drawn;
  // Inside VTK's depth peeling, which draws every volume in each of its stages: drawn in the
  // current stage, until the volume's own draw in that stage passes.
  std::set<vtkVolume*> DrawnInStage;
  // The first volume of a group drawn in this frame (or stage), until its own next draw: no
  // other volume's group takes it again.
  std::set<vtkVolume*> Leaders;
};
std::map<vtkRenderer*, RendererFrame>& Frames()
{
  static std::map<vtkRenderer*, RendererFrame> frames;
  return frames;
}

void RendererEvent(vtkObject* caller, unsigned long event, void*, void*);

// The marks of `renderer`'s current frame, or null where it has none.
RendererFrame* MarksOf(vtkRenderer* renderer)
{
  auto& frames = Frames();
  auto it = frames.find(renderer);
  return it != frames.end() && it->second.Renderer == renderer ? &it->second : nullptr;
}

// The marks of `renderer`'s current frame, cleared at its next StartEvent.
RendererFrame& FrameOf(vtkRenderer* renderer)
{
  RendererFrame& frame = Frames()[renderer];
  if (!frame.Renderer)
  {
    // A renderer seen for the first time (or a new one at a deleted one's address).
    frame = RendererFrame();
    frame.Renderer = renderer;
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(RendererEvent);
    renderer->AddObserver(vtkCommand::StartEvent, callback);
    renderer->AddObserver(vtkCommand::DeleteEvent, callback);
  }
  return frame;
}

void RendererEvent(vtkObject* caller, unsigned long event, void*, void*)
{
  auto& frames = Frames();
  auto it = frames.find(static_cast<vtkRenderer*>(caller));
  if (it == frames.end())
  {
    return;
  }
  if (event == vtkCommand::DeleteEvent)
  {
    frames.erase(it);
  }
  else
  {
    it->second.Drawn.clear();
    it->second.DrawnInStage.clear();
    it->second.Leaders.clear();
  }
}

// Whether a box (world bounds) lies wholly outside one plane of the view frustum of `matrix`
// (world to clip coordinates): nothing of it can be seen.
bool OutsideFrustum(const double bounds[6], vtkMatrix4x4* matrix)
{
  int outside[6] = { 0, 0, 0, 0, 0, 0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
      bounds[4 + ((corner >> 2) & 1)], 1.0 };
    double c[4];
    matrix->MultiplyPoint(p, c);
    for (int k = 0; k < 3; ++k)
    {
      outside[2 * k] += c[k] < -c[3] ? 1 : 0;
      outside[2 * k + 1] += c[k] > c[3] ? 1 : 0;
    }
  }
  return std::find(outside, outside + 6, 8) != outside + 6;
}

// `alone`: how the volume is drawn instead ("on its own", or with the others left out).
std::string Warning(const std::string& reason, const std::string& alone = "on its own")
{
  return "This volume overlaps another volume of a tiled ray-cast mapper, but " + reason +
    ": it is drawn " + alone +
    ", before or after the others by the depth of its bounds, not mixed with them where they "
    "overlap (docs/mapper.md, \"Overlapping volumes\").";
}
} // anonymous namespace

//------------------------------------------------------------------------------
std::string vtkTiledRayCastVolumeGroup::Refusal(
  vtkTiledRayCastVolumeMapper* mapper, vtkVolume* volume, bool noCompute, bool lit)
{
  vtkVolumeProperty* property = volume->GetProperty();
  if (mapper->GetNumberOfInputConnections(0) == 0 || !mapper->GetInputDataObject(0, 0) || !property)
  {
    return "it has no input or property";
  }
  if (mapper->GetPipeline() == vtkTiledRayCastVolumeMapper::FRAGMENT_PIPELINE || noCompute)
  {
    return "it uses the fragment pipeline (a group needs the compute pipeline)";
  }
  if (mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return "its blend mode is not composite";
  }
  const int mode = mapper->GetIntegrationMode();
  if (mode != vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION &&
    mode != vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION)
  {
    return "its integration is a pre-integration table (a group integrates with partial "
           "pre-integration, which the automatic mode, the default, takes in a group)";
  }
  if (mapper->GetMeshLayout() != vtkTiledRayCastVolumeMapper::COMPACT_LAYOUT)
  {
    return "it uses the paper's mesh layout";
  }
  if (mapper->GetNumberOfClippingPlanes() > 0)
  {
    return "it has clipping planes";
  }
  if (property->GetShade() || lit)
  {
    return "it is shaded or uses gradient opacity";
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastVolumeGroup::Overlap(vtkVolume* a, vtkVolume* b)
{
  const double* p = a->GetBounds();
  double ba[6];
  std::copy(p, p + 6, ba);
  const double* bb = b->GetBounds();
  for (int i = 0; i < 3; ++i)
  {
    if (!(ba[2 * i] <= bb[2 * i + 1] && bb[2 * i] <= ba[2 * i + 1]))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<vtkTiledRayCastVolumeGroup::Candidate> vtkTiledRayCastVolumeGroup::Select(
  const std::vector<Candidate>& candidates, vtkVolume* self)
{
  // A mapper drawing several volumes holds one frame's state: those volumes are drawn alone.
  auto shared = [&candidates](const Candidate& c)
  {
    return std::count_if(candidates.begin(), candidates.end(),
             [&c](const Candidate& o) { return o.Member == c.Member; }) > 1;
  };
  auto refusal = [&shared](const Candidate& c)
  {
    return shared(c) ? std::string("its mapper draws another volume too")
                     : c.Member->GetGroupRefusal(c.Volume, false);
  };
  std::vector<Candidate> alone;
  std::vector<Candidate> eligible;
  for (const Candidate& c : candidates)
  {
    if (c.Volume == self)
    {
      alone.push_back(c);
    }
    if (refusal(c).empty())
    {
      eligible.push_back(c);
    }
  }
  if (alone.empty())
  {
    return alone;
  }
  const Candidate me = alone.front();
  const std::string reason = refusal(me);
  if (!reason.empty())
  {
    for (const Candidate& c : candidates)
    {
      if (c.Volume != self && Overlap(self, c.Volume))
      {
        me.Member->WarnGroupOnce(Warning(reason));
        break;
      }
    }
    return alone;
  }
  // The volumes that overlap this one, directly or through others.
  std::vector<bool> in(eligible.size(), false);
  std::vector<size_t> todo;
  for (size_t i = 0; i < eligible.size(); ++i)
  {
    if (eligible[i].Volume == self)
    {
      in[i] = true;
      todo.push_back(i);
    }
  }
  while (!todo.empty())
  {
    const size_t i = todo.back();
    todo.pop_back();
    for (size_t j = 0; j < eligible.size(); ++j)
    {
      if (!in[j] && Overlap(eligible[i].Volume, eligible[j].Volume))
      {
        in[j] = true;
        todo.push_back(j);
      }
    }
  }
  std::vector<Candidate> group = alone;
  for (size_t i = 0; i < eligible.size(); ++i)
  {
    if (in[i] && eligible[i].Volume != self)
    {
      group.push_back(eligible[i]);
    }
  }
  if (group.size() > static_cast<size_t>(MaximumVolumes))
  {
    me.Member->WarnGroupOnce(Warning(std::to_string(group.size()) +
      " volumes overlap, directly or through others, and one traversal is composed for at most " +
      std::to_string(MaximumVolumes)));
    return alone;
  }
  return group;
}

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeGroup::Render(
  vtkRenderer* renderer, vtkOpenGLRenderWindow* window, const std::vector<Candidate>& group)
{
  if (group.size() < 2)
  {
    return 0;
  }
  // Each volume's own CPU work (only what changed); the first sets the image size.
  int rays[2] = { 0, 0 };
  vtkTiledRayCastGroupMember* first = group.front().Member;
  if (!first->PrepareGroupFrame(renderer, group.front().Volume, window, true, rays))
  {
    return 0;
  }
  std::vector<vtkTiledRayCastGroupMember*> members;
  std::vector<vtkVolume*> volumes;
  // One traversal takes the volumes whose textures the free texture units hold.
  const int limit = first->GetGroupTextureUnits();
  int units = 0;
  for (const Candidate& c : group)
  {
    if (c.Member != first && Marked(renderer, c.Volume))
    {
      continue; // drawn already in this frame (or stage), by a group that took it
    }
    if (c.Member != first && !c.Member->PrepareGroupFrame(renderer, c.Volume, window, false, rays))
    {
      continue; // it draws nothing: its own Render() says why
    }
    const std::string refusal = c.Member->GetGroupRefusal(c.Volume, true);
    if (!refusal.empty())
    {
      c.Member->WarnGroupOnce(Warning(refusal));
      if (c.Member == first)
      {
        return 0;
      }
      continue;
    }
    const int needs = vtkTiledRayCastGroupTraversal::GetTextureUnits(c.Member->GetGroupInputs());
    if (units + needs > limit)
    {
      if (c.Member == first)
      {
        return 0;
      }
      c.Member->WarnGroupOnce(Warning("the " + std::to_string(members.size()) +
          " volumes before it fill one traversal: its compute shader has " + std::to_string(limit) +
          " texture units for the volumes' own textures here, and this volume takes " +
          std::to_string(needs) + " (its mesh's texture buffers, transfer function and visible " +
          "tets)",
        "on its own (or mixed with the other volumes left out, where they overlap)"));
      continue;
    }
    units += needs;
    members.push_back(c.Member);
    volumes.push_back(c.Volume);
  }
  if (members.size() < 2 || !first->DrawGroup(window, rays, members))
  {
    return 0;
  }
  const int count = static_cast<int>(members.size());
  const bool stage = vtkTiledRayCastVolumetricPeel::FindPass(group.front().Volume) != nullptr;
  FrameOf(renderer).Leaders.insert(volumes[0]);
  for (size_t i = 1; i < members.size(); ++i)
  {
    MarkDrawn(renderer, volumes[i], stage);
    members[i]->FinishGroupFrame(count);
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVolumeGroup::MarkDrawn(vtkRenderer* renderer, vtkVolume* volume, bool stage)
{
  RendererFrame& frame = FrameOf(renderer);
  (stage ? frame.DrawnInStage : frame.Drawn).insert(volume);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastVolumeGroup::Marked(vtkRenderer* renderer, vtkVolume* volume)
{
  const RendererFrame* frame = MarksOf(renderer);
  return frame &&
    (frame->Drawn.count(volume) > 0 || frame->DrawnInStage.count(volume) > 0 ||
      frame->Leaders.count(volume) > 0);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastVolumeGroup::WasDrawn(vtkRenderer* renderer, vtkVolume* volume)
{
  RendererFrame* frame = MarksOf(renderer);
  if (!frame)
  {
    return false;
  }
  // A group's first volume is drawn again (its next stage of VTK's depth peeling): another
  // group may take it from then on.
  frame->Leaders.erase(volume);
  // A mark of the current stage of VTK's depth peeling serves the volume's draw in that stage.
  return frame->Drawn.count(volume) > 0 || frame->DrawnInStage.erase(volume) > 0;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastVolumeGroup::MaySplit(
  const std::vector<Candidate>& set, const Candidate& drawer)
{
  // The textures the volumes' last frames asked for (Render() counts again once they are
  // prepared), against what the drawing volume's window has free.
  int units = 0;
  for (const Candidate& c : set)
  {
    units += vtkTiledRayCastGroupTraversal::GetTextureUnits(c.Member->GetGroupInputs());
  }
  return set.size() > 1 && units > drawer.Member->GetGroupTextureUnits();
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastVolumeGroup::RenderInDepthOrder(
  vtkRenderer* renderer, const std::vector<Candidate>& candidates, vtkVolume* self)
{
  // Set while the volumes are drawn: their own Render() draws them the usual way.
  static bool ordering = false;
  vtkCamera* camera = renderer->GetActiveCamera();
  if (ordering || candidates.size() < 2 || !camera)
  {
    return false;
  }
  vtkMatrix4x4* worldToClip =
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0);
  // What is drawn together: each group of overlapping volumes (as its first volume's mapper
  // would find it), each other volume alone; with the world bounds of each.
  std::vector<std::vector<Candidate>> sets;
  std::vector<vtkTiledRayCastVolumeOrder::Bounds> boxes;
  std::set<vtkVolume*> placed;
  const Candidate* drawer = nullptr;
  bool drawerInView = false;
  for (const Candidate& c : candidates)
  {
    drawer = c.Volume == self ? &c : drawer;
    if (placed.count(c.Volume))
    {
      continue;
    }
    std::vector<Candidate> set = Select(candidates, c.Volume);
    vtkTiledRayCastVolumeOrder::Bounds box = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX,
      VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
    bool holdsDrawer = false;
    for (const Candidate& member : set)
    {
      placed.insert(member.Volume);
      holdsDrawer = holdsDrawer || member.Volume == self;
      const double* b = member.Volume->GetBounds();
      for (int k = 0; k < 3; ++k)
      {
        box[2 * k] = std::min(box[2 * k], b[2 * k]);
        box[2 * k + 1] = std::max(box[2 * k + 1], b[2 * k + 1]);
      }
    }
    if (!OutsideFrustum(box.data(), worldToClip))
    {
      sets.push_back(set);
      boxes.push_back(box);
      drawerInView = drawerInView || holdsDrawer;
    }
  }
  // A volume VTK draws though its bounds are out of view draws only itself.
  if (!drawer || !drawerInView)
  {
    return false;
  }
  // Inside VTK's depth peeling, a stage of it: the sets go over one another in the stage's
  // accumulation, which the calling volume's mapper then composites once; also one set whose
  // volumes would not all fit one traversal (Render() splits it), whose parts the pass would
  // otherwise blend with MAX.
  const bool stage = vtkTiledRayCastVolumetricPeel::FindPass(self) != nullptr;
  if (sets.size() < 2 && !(stage && sets.size() == 1 && MaySplit(sets.front(), *drawer)))
  {
    return false;
  }
  if (!drawer->Member->BeginDepthOrder(renderer, self, stage))
  {
    return false;
  }
  ordering = true;
  for (size_t index : vtkTiledRayCastVolumeOrder::BackToFront(boxes, camera))
  {
    // The set's first volume draws its group; a member the group could not take after all
    // (its frame found shading, say) is drawn right after it, still in the set's turn.
    for (const Candidate& member : sets[index])
    {
      if (!WasDrawn(renderer, member.Volume))
      {
        member.Volume->RenderVolumetricGeometry(renderer);
      }
      // Inside the peeling VTK draws every volume in each stage: each but the calling one is
      // marked for its draw in this stage (a mark the group made was taken above).
      if (!stage || member.Volume != self)
      {
        MarkDrawn(renderer, member.Volume, stage);
      }
    }
  }
  ordering = false;
  drawer->Member->FinishDepthOrder(renderer, self, stage, static_cast<int>(sets.size()));
  return true;
}
