/**
 * @class   vtkDeepShadowCompositeSurfaceMapper
 * @brief   Draws the polydata leaves of a composite dataset with vtkDeepShadowPolyDataMapper.
 *
 * ParaView's geometry representations hand their mappers a vtkMultiBlockDataSet (one block
 * per piece or per block of the source); vtkDeepShadowPolyDataMapper draws one vtkPolyData.
 * This mapper joins the leaves into one polydata (again only when the input changed) and
 * draws it with an inner vtkDeepShadowPolyDataMapper, handing it the colouring settings the
 * representation set here (lookup table, array, scalar mode, ...) at each render. A plain
 * vtkPolyData input is drawn as it is.
 *
 * What is lost against vtkCompositePolyDataMapper2: per-block colours, opacities and
 * visibilities (every leaf is drawn with the actor's property), and selection highlighting.
 * Leaves joined by vtkAppendPolyData keep only the arrays they all have.
 */
#ifndef vtkDeepShadowCompositeSurfaceMapper_h
#define vtkDeepShadowCompositeSurfaceMapper_h

#include "vtkDeepShadowParaViewModule.h" // For export macro
#include "vtkMapper.h"
#include "vtkNew.h" // For ivars

class vtkDeepShadowPolyDataMapper;
class vtkPolyData;
class vtkVolume;

class VTKDEEPSHADOWPARAVIEW_EXPORT vtkDeepShadowCompositeSurfaceMapper : public vtkMapper
{
public:
  static vtkDeepShadowCompositeSurfaceMapper* New();
  vtkTypeMacro(vtkDeepShadowCompositeSurfaceMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The mapper that draws the joined leaves (its shadowing volume, bias, counters). */
  vtkDeepShadowPolyDataMapper* GetSurfaceMapper() { return this->Inner; }

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  double* GetBounds() override;
  using vtkMapper::GetBounds;
  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /** Times the leaves were joined anew (observability: once per changed input). */
  vtkGetMacro(Joins, int);
  /** Joins the input's leaves for the surface mapper if the input changed since the last join. */
  void Join();

protected:
  vtkDeepShadowCompositeSurfaceMapper();
  ~vtkDeepShadowCompositeSurfaceMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkDeepShadowCompositeSurfaceMapper(const vtkDeepShadowCompositeSurfaceMapper&) = delete;
  void operator=(const vtkDeepShadowCompositeSurfaceMapper&) = delete;

  /** Gives the inner mapper this mapper's colouring settings (only those that changed). */
  void PassSettings();

  vtkNew<vtkDeepShadowPolyDataMapper> Inner;
  vtkNew<vtkPolyData> Joined;
  vtkMTimeType JoinedTime = 0;
  const void* JoinedInput = nullptr;
  int Joins = 0;
};

#endif
