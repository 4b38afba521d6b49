// Internal: plain GL objects the techniques own by name: nearest-filtered 2D array textures
// and shader storage buffers that grow.
#ifndef vtkDeepShadowGLObjects_h
#define vtkDeepShadowGLObjects_h

class vtkOpenGLRenderWindow;

namespace deepshadow
{
/**
 * A 2D array texture of `layers` layers, nearest filtered, clamped to its edge (texelFetch
 * and image stores need no mipmaps). Bound on a unit of VTK's texture unit manager while it
 * is made, so that VTK's cached state stays right. 0 if the GL failed (glGetError says).
 */
unsigned int NewArrayTexture(vtkOpenGLRenderWindow* window, unsigned int format, int width, int height, int layers);
/** Deletes it and sets the name to 0 (nothing for 0). */
void DeleteTexture(unsigned int& texture);
/** A shader storage buffer of at least `bytes`, grown (never shrunk); `allocated` its size. */
void EnsureStorageBuffer(unsigned int& buffer, long long& allocated, long long bytes);
/** Deletes it and sets the name and its size to 0 (nothing for 0). */
void DeleteBuffer(unsigned int& buffer, long long& allocated);
}

#endif
