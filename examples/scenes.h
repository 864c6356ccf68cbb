// scenes.h — the example scenes, shared by the example programs (which write PNGs) and the image tests
// (which compare them with golden images).
#pragma once

#include <string>

#include <softgl/softgl.h>

namespace scenes {

/// A triangle with red, green and blue corners, colours interpolated across it (DrawArrays, two buffers).
softgl::Image Triangle(int width, int height);

/// A lit cube with per-face colours, rotated by `angle` radians about a tilted axis (DrawElement, interleaved
/// vertex buffer with normalized unsigned-byte colours, depth test, back-face culling).
softgl::Image Cube(int width, int height, float angle);

/// A torus drawn with PolygonMode(LINE) over a filled, dimmed copy, and its vertices as points.
softgl::Image Wireframe(int width, int height);
/// The geometry stage: a torus shaded with its wireframe in one pass (edge distances from the geometry stage), and
/// a torus with its face normals drawn as lines made from its triangles.
softgl::Image GeometryStage(int width, int height);

/// A camera standing on a checkered floor that runs behind it, with a cube crossing the near plane: triangles are
/// clipped by the near plane and the side planes, and the checks show perspective-correct interpolation.
softgl::Image Clipped(int width, int height);

/// A torus and a cube outlined in orange: each object writes 1 to the stencil buffer, then a slightly larger copy is
/// drawn flat where the stencil is not 1, leaving only the silhouette.
softgl::Image StencilOutline(int width, int height);

/// A cube above a mirror set into a checkered floor: the mirror marks the stencil buffer, the reflected cube is
/// drawn only where the stencil says "mirror" (with the winding flipped), then the mirror is blended over it.
softgl::Image Mirror(int width, int height);

/// Translucent panels over an opaque scene, drawn back to front with SRC_ALPHA / ONE_MINUS_SRC_ALPHA and depth
/// writes off (left), and the same panels in the wrong order (right), which shows why the order matters.
softgl::Image Transparency(int width, int height);

/// Round decals on two cube faces, coplanar with them: without polygon offset (left) they fight with the face;
/// with PolygonOffset(-1, -1) (right) they sit cleanly on top.
softgl::Image Decals(int width, int height);

/// A receding floor and a cube with a mipmapped texture: the floor's left third NEAREST (moire in the distance), the
/// middle trilinear (LINEAR_MIPMAP_LINEAR, the level of detail following the screen-space derivatives), the right
/// trilinear with 16x anisotropic filtering (sharper at grazing angles).
softgl::Image TexturedCube(int width, int height);

/// sRGB done right and wrong: left, an sRGB texture (decoded before filtering) lit and blended in linear light into
/// an sRGB framebuffer (FRAMEBUFFER_SRGB); right, the same scene with the encoded colours taken as linear. The
/// distant floor keeps its brightness on the left and darkens on the right, the sphere's light falls off softly on
/// the left, and where the red and green panels overlap the left stays bright.
softgl::Image Srgb(int width, int height);

/// Compressed textures: a receding floor and three cubes with one pattern as RGBA8 (left), DXT1 from a DDS file
/// (middle: 8 times smaller, each 4 x 4 block's colours on a line between two) and DXT5 (right: colours as DXT1,
/// plus an alpha block; the dark checks a third opaque, blended over the sky on the floor).
softgl::Image CompressedTextures(int width, int height);

/// Multisampling: the same scene (a lit torus and thin spokes) with 1, 2, 4 and 8 samples a pixel, left to right,
/// each rendered at half size into a multisampled framebuffer object, resolved by BlitFramebuffer and magnified 2x
/// so that the pixels show: staircase edges on the left, smoother with every doubling of the samples.
softgl::Image Multisample(int width, int height);

/// Sample shading: a lit sphere striped along its longitudes (a hard step in the fragment shader) with 4 samples a
/// pixel, the shader run once per pixel (left) and once per sample with SAMPLE_SHADING and MinSampleShading(1)
/// (right), magnified 2x: the silhouette is smooth in both, the stripes' edges only on the right.
softgl::Image SampleShading(int width, int height);

/// Colour formats for small memory: a lit torus in RGBA8 (4 bytes a pixel), RGB565, RGB5_A1 and RGBA4 (2 bytes
/// a pixel), left to right, each with a DEPTH_COMPONENT16 depth buffer: the smooth shading keeps 256 steps a
/// channel on the left, 32 or 64 in the middle panels, and shows bands of 16 on the right.
softgl::Image SmallFormats(int width, int height);

/// Shadow mapping: depth from the light into a depth texture through a framebuffer object, then the lit pass
/// samples it with depth comparison, 3 x 3 taps of 2 x 2 percentage-closer filtering.
softgl::Image ShadowMap(int width, int height);

/// Cascaded shadow maps: three shadow maps, one for each stretch of the view's depth (near, middle, far), rendered
/// into the layers of one depth texture array through FramebufferTextureLayer; the lit pass picks each fragment's
/// cascade by its depth and compares in that layer. Left: the shadowed scene, two rows of pillars running 50 units
/// away; right: the same, each cascade tinted (red near, green middle, blue far).
softgl::Image CascadedShadows(int width, int height);

/// Post-processing: the scene rendered into a half-float (RGBA16F, HDR) texture, then one full-screen pass tone maps it;
/// right of the middle it is blurred first.
softgl::Image PostProcess(int width, int height);

/// Environment mapping: a sphere and a gold torus reflect a cube map (computed per texel, mipmapped), which is
/// also drawn as the background.
softgl::Image EnvironmentMap(int width, int height);

/// A field of 10,000 lit cubes drawn by one DrawElementsInstanced: gl_InstanceID places each on a 100 x 100 grid,
/// attributes with divisor 1 give its height and colour.
softgl::Image Instancing(int width, int height);

/// 1,200 lit cubes along a double helix from one instanced draw: each cube's model matrix read from a buffer
/// texture by gl_InstanceID, its colour from a palette (a second buffer texture) at an index an integer attribute
/// gives.
softgl::Image BufferTextures(int width, int height);

/// Picking: 24 objects drawn once more into an R32UI texture, each fragment writing its object's id (an integer
/// colour output), and the ids under five clicks read back by ReadPixels(RED_INTEGER, UNSIGNED_INT); the scene shows
/// the picked objects in colour, the others dimmed, the clicks as crosses (red: nothing there), and the id buffer
/// in false colours (texelFetch of the integer texture) in the top right corner.
softgl::Image Picking(int width, int height);

/// Deferred shading: a G-buffer of three targets (albedo RGBA8, normal and position RGBA16F), each cleared to its
/// own value by ClearBufferfv; a decal pass writes the albedo target alone (ColorMaski masks the others); a lighting
/// pass reads the three by texelFetch and lights every pixel by six point lights. Along the bottom, the targets.
softgl::Image Deferred(int width, int height);

/// A fountain of 1,500 particles drawn as point sprites in one draw: gl_PointSize by distance, a soft disc shaped
/// from gl_PointCoord, additive blending.
softgl::Image Particles(int width, int height);

/// A fountain simulated on the vertex stage: each step recorded by transform feedback into the other of two
/// buffers (RASTERIZER_DISCARD), snapshots drawn as points that leave trails.
softgl::Image FeedbackParticles(int width, int height);

// ---- The guided tour (docs/tour.md): one picture per stage, each quantity made visible by a shader ----------

/// Clipping: left, a floor triangle seen from above with the camera's view volume (near plane in yellow), red where
/// clip-space z < -w, and the polygon Sutherland-Hodgman keeps (white); right, the camera's view of what is kept.
softgl::Image TourClipping(int width, int height);
/// Coverage: four triangles (and a fifth) in a 20 x 10 framebuffer, added together, magnified with the pixel grid
/// and centres: every centre on a shared edge belongs to exactly one triangle (the tie rule).
softgl::Image TourCoverage(int width, int height);
/// Barycentric weights as red, green and blue with lines every 0.1: left linear in window space, right
/// perspective-correct, on a triangle lying on the ground.
softgl::Image TourBarycentric(int width, int height);
/// The viewport: one drawing in normalized device coordinates (a grid, the axes, a triangle) through three viewports.
softgl::Image TourViewport(int width, int height);
/// The depth buffer: a scene, its DEPTH_COMPONENT32F buffer as grey, and the eye distance recovered from it.
softgl::Image TourDepth(int width, int height);
/// Texture coordinates on a receding square of two triangles: affine (NoPerspective) left, perspective-correct
/// right.
softgl::Image TourPerspective(int width, int height);
/// Face culling: a sphere and a torus cut open, front faces blue, back faces orange; left no culling, right
/// CullFace(BACK).
softgl::Image TourCulling(int width, int height);
/// Binning: the 64 x 64 tiles of a scene and how many primitives each was given (Context::CountTilePrimitives).
softgl::Image TourTiles(int width, int height);
/// Mipmap levels: a texture whose every level has its own colour on a receding floor, NEAREST_MIPMAP_NEAREST,
/// LINEAR_MIPMAP_LINEAR and 16x anisotropic, left to right.
softgl::Image TourMipmapLevels(int width, int height);
/// Lines: a segment drawn by the diamond-exit rule (above) and by the classic Bresenham loop (below), magnified
/// with each pixel's diamond.
softgl::Image TourLines(int width, int height);
/// Multisampling: an edge in a framebuffer of 4 samples a pixel, magnified: each sample a dot in its own colour,
/// each pixel the resolved average.
softgl::Image TourMultisample(int width, int height);

/// The model in `path` (any format assimp reads), framed by its bounding box from (azimuth, elevation) degrees,
/// three-point lit, drawn with the built-in shader named "unlit", "phong" or "pbr", into a framebuffer of 4 samples
/// a pixel. An empty image, with the reason in `error`, when the model cannot be loaded.
softgl::Image ModelView(const std::string& path, const std::string& shader, int width, int height, float azimuth,
                        float elevation, std::string* error = nullptr, float point_size = 1.0f);

/// Model files of points and lines alone, written for the models example and its golden images: a PLY point cloud
/// of 20,000 coloured points (a spiral galaxy: vertices with colours, no faces) and an OBJ of one closed polyline
/// (a (3, 7) torus knot of 720 segments, `l` elements only). False when the file cannot be written.
bool WritePointCloudPly(const std::string& path);
bool WriteTorusKnotObj(const std::string& path);

/// The folder of Debian's assimp-testmodels.
inline constexpr const char* kTestModels = "/usr/share/assimp/models";

}  // namespace scenes
