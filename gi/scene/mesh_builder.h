#pragma once
// Building meshes in code, for the built-in scene generators: flat-shaded quads and boxes,
// smooth cylinders and displaced grids, with one submesh per run of a material.
#include "gi/scene/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lumina::scene {

class MeshBuilder {
public:
    explicit MeshBuilder(std::string name);

    // Triangles added from now on use `material`.
    void material(uint32_t material);

    uint32_t vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv);
    void triangle(uint32_t a, uint32_t b, uint32_t c);

    // A planar quad, front face where a, b, c, d run counter-clockwise; normal from the winding.
    void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d);
    // The same quad, wound so that its front faces away from `inside`.
    void quadFacingAwayFrom(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                            const glm::vec3& inside);
    // An axis-aligned box; `inward` puts the front faces inside (a room). Faces whose bit is
    // set in `skipFaces` are left out: bit 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z.
    void box(const glm::vec3& min, const glm::vec3& max, bool inward = false, uint32_t skipFaces = 0);
    // One face of a room's inside, the box from `min` to `max` (face numbered as in box()), facing
    // into the room and cut into quads at `xs` and `zs` (sorted, from min to max along x and z; the
    // walls span the full height). Faces cut at the same xs and zs share every edge end to end, so
    // the room is watertight: where one quad's edge ends part-way along its neighbour's (a
    // T-junction), the rasteriser can miss a pixel on the seam and show what lies behind it.
    // `skip(i, k)` leaves out the floor or ceiling cell between xs[i..i+1] and zs[k..k+1] (an opening).
    void roomFace(const glm::vec3& min, const glm::vec3& max, const std::vector<float>& xs,
                  const std::vector<float>& zs, uint32_t face,
                  const std::function<bool(size_t, size_t)>& skip = {});
    // A smooth open cylinder along +y, with `segments` around and `rings` along it.
    void cylinder(const glm::vec3& base, float radius, float height, uint32_t segments, uint32_t rings);
    // A grid of (nu x nv) quads over origin + s*u + t*v, s and t in [0, 1], displaced by
    // offset(s, t); normals from the displaced surface; front face along cross(u, v).
    void grid(const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, uint32_t nu, uint32_t nv,
              const std::function<glm::vec3(float, float)>& offset);

    uint64_t triangleCount() const { return mesh_.indices.size() / 3; }
    Mesh finish();

private:
    Mesh mesh_;
    uint32_t material_ = 0;
};

} // namespace lumina::scene
