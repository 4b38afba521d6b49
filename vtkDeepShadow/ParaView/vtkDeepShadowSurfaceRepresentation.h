/**
 * @class   vtkDeepShadowSurfaceRepresentation
 * @brief   ParaView's surface representation, drawn in the shadows of the view's volumes.
 *
 * The "Shadowed Surface" representation type of the DeepShadow plugin, offered for polydata,
 * unstructured grids, image data and structured grids. Everything ParaView's "Surface" does
 * (colouring by an array and its colour map, the property's colour, opacity, ambient, diffuse
 * and specular, the actor's placement) goes through unchanged: the superclass drives the
 * mapper, a vtkDeepShadowCompositeSurfaceMapper, with vtkMapper's API. Added: the surface
 * receives the shadows of the first visible "Shadowed Volume" of the view (the volume drawn
 * by a vtkDeepShadowVolumeMapper with a technique), with that volume's technique, as the
 * volume's own shadow ground does, and casts into every Shadowed Volume's structures (each
 * gathers the view's Shadowed Surfaces at the start of a render, again only when one of them
 * changed: vtkDeepShadowVolumeRepresentation::GetCastingMeshes()), as meshes do under
 * vtkDeepShadowPass: an opaque surface stops the light, a translucent one lets its
 * transmission through.
 *
 * Limits of this version:
 * - under MPI the surface is drawn lit, without shadows, and casts none, said once in Output
 *   Messages (a rank's lookups see its own brick and those in front of it, not yet every
 *   brick between the light and a surface);
 * - blocks are drawn alike, with the display's property (no per-block colour or visibility);
 * - a backface style other than "Follow Frontface" draws the back faces as ParaView does,
 *   without shadows.
 */
#ifndef vtkDeepShadowSurfaceRepresentation_h
#define vtkDeepShadowSurfaceRepresentation_h

#include "vtkDeepShadowParaViewModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkRenderer;
class vtkVolume;

class VTKDEEPSHADOWPARAVIEW_EXPORT vtkDeepShadowSurfaceRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkDeepShadowSurfaceRepresentation* New();
  vtkTypeMacro(vtkDeepShadowSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The volume whose shadows the surface received at the last render; null: none. */
  vtkVolume* GetShadowingVolume() const { return this->ShadowingVolume; }

protected:
  vtkDeepShadowSurfaceRepresentation();
  ~vtkDeepShadowSurfaceRepresentation() override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;
  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* in, vtkInformation* out) override;

private:
  vtkDeepShadowSurfaceRepresentation(const vtkDeepShadowSurfaceRepresentation&) = delete;
  void operator=(const vtkDeepShadowSurfaceRepresentation&) = delete;

  /** Finds the view's first visible volume with a shadow technique and gives it to the mappers. */
  void FindShadowingVolume();

  vtkRenderer* Renderer = nullptr; // the view's, while the representation is in one
  vtkVolume* ShadowingVolume = nullptr;
  bool SaidRanks = false;
};

#endif
