// The camera: a pinhole, or a camera model (CameraModel) that a lesson provides and registers
// under the scene keyword that selects it. It generates rays and answers what bidirectional
// methods ask of it: the emitted importance W_e, the densities of its rays, the raster position of
// a point.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include "ray.h"
#include "registry.h"
#include "rng.h"

namespace ps {

class Camera;

// A camera whose rays leave points other than one pinhole (a lens, say): where a camera path
// starts (its point z) and what the camera answers about the rays through z. A lesson provides it
// and registers it (CameraModelType); every algorithm that asks the camera through Camera's
// functions of z (below) renders it. Unlike the pinhole's, its points are no delta position:
// rays can hit them (hit()).
class CameraModel {
public:
    virtual ~CameraModel() = default;
    // A point z of the camera for u in [0, 1)^2, and its density per unit area.
    virtual Vec3 samplePoint(const Vec2& u) const = 0;
    virtual float pdfPoint() const = 0;
    // The ray from z through raster position `raster`.
    virtual Ray ray(const Vec2& raster, const Vec3& z) const = 0;
    // Where the ray (z, dir) (dir of any length) lands on the image; false outside it.
    virtual bool rasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const = 0;
    // The importance W_e(z, dir) along the unit direction dir, normalised over the camera's points
    // and the whole image, and the solid-angle density of dir at z for uniform raster positions.
    virtual float We(const Vec3& z, const Vec3& dir) const = 0;
    virtual float pdfDirection(const Vec3& z, const Vec3& dir) const = 0;
    // Where a ray meets the camera's points: the distance t in (0, ray.tMax) and the point z.
    virtual bool hit(const Ray& ray, float& t, Vec3& z) const = 0;
    // The scene file's words for it, for messages ("lens 0.02 focus 1.5").
    virtual std::string describe() const = 0;
};

// What a camera model's maker gets from the scene file's camera line: its keywords' values, read
// with the loader's rules and messages, and fail, which throws InputError naming the scene file
// and line.
struct CameraModelArgs {
    float targetDistance = 0.0f;  // from the eye to the line's target
    std::function<bool(const std::string& key)> has;
    std::function<float(const std::string& key, float def)> number;  // def if the line lacks key
    std::function<std::string(const std::string& key)> text;         // the value as written
    std::function<void(const std::string& problem)> fail;            // never returns
};

// How a scene file's camera line makes a camera model (Registry<CameraModelType>, keyed by the
// keyword that selects it): its keywords with the number of values each takes, and the maker,
// called when the line has one of them with the pinhole camera the line describes. It returns
// nullptr for the pinhole (a lens of radius 0, say).
struct CameraModelType {
    std::vector<std::pair<std::string, int>> keywords;
    std::shared_ptr<const CameraModel> (*make)(const Camera& pinhole, const CameraModelArgs& args) = nullptr;
};

class Camera {
public:
    Camera() = default;
    // fovY: full vertical field of view in degrees, 0 < fovY < 180. A pinhole; setModel gives it
    // a camera model.
    Camera(const Vec3& eye, const Vec3& target, const Vec3& up, float fovY, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return eye_; }  // the pinhole (a camera model's centre)
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }  // the raster's +x on the image plane
    const Vec3& up() const { return up_; }        // the raster's -y on the image plane
    // A pinhole is a delta position: rays cannot hit it. A camera model's points they can.
    bool isPinhole() const { return !model_; }
    const CameraModel* model() const { return model_.get(); }
    void setModel(std::shared_ptr<const CameraModel> model) { model_ = std::move(model); }
    int line = 0;  // the scene file line of the camera (for messages), 0 if none

    // ---- the pinhole -------------------------------------------------------------------------

    // Ray through raster position (x, y) in [0, width) x [0, height); y grows downward.
    // Lesson 0's piece (solutions/00-rays/rays.cpp). The pinhole's ray, also with a camera model.
    Ray generateRay(const Vec2& raster) const;

    // Raster position where the direction from the pinhole towards p crosses the image;
    // false if p is behind the camera or outside the image.
    bool rasterPosition(const Vec3& p, Vec2& raster) const;
    // The same for a direction dir (any length) leaving the pinhole. Prefer it to
    // rasterPosition(position() + dir): adding dir to a far-off eye rounds it.
    bool rasterOfDirection(const Vec3& dir, Vec2& raster) const;

    // Importance emitted along dir (unit, from the pinhole), normalised over the whole image:
    // W_e = 1 / (A cos^4 theta) inside the image, 0 outside, where A is the area of the image
    // rectangle at distance 1. Then the integral of W_e cos(theta) over the image's directions
    // is 1. A single pixel's sensor is W_e * width * height restricted to that pixel.
    // Lesson 4's piece: implemented in solutions/04-measurement/importance.cpp (reference) or
    // assignments/04-measurement/importance.cpp (yours), not in camera.cpp.
    float We(const Vec3& dir) const;

    // Solid-angle pdf of dir for rays through uniformly chosen raster positions:
    // pdf = 1 / (A cos^3 theta) (0 outside the image).
    float pdfDirection(const Vec3& dir) const;

    // Area of the image rectangle at distance 1 from the pinhole.
    float imagePlaneArea() const { return 4.0f * tanHalfX_ * tanHalfY_; }

    // ---- the camera point z of a path: the pinhole, or a point of the camera model ------------
    // Algorithms that connect to the camera ask these, so one piece of code serves every camera; for a pinhole each is
    // exactly the pinhole's function above (z is position(), u is not used), else the model's.

    // The camera point for u, and its density: 1 for the pinhole (a delta position, chosen with
    // probability 1), the model's per unit area.
    Vec3 samplePoint(const Vec2& u) const { return model_ ? model_->samplePoint(u) : eye_; }
    float pdfPoint() const { return model_ ? model_->pdfPoint() : 1.0f; }
    // The pinhole's point, or a model's point drawn with the next two numbers of rng (none for a pinhole).
    Vec3 samplePoint(Rng& rng) const { return model_ ? model_->samplePoint(rng.uniform2()) : eye_; }
    // The ray from camera point z through raster position `raster`.
    Ray generateRay(const Vec2& raster, const Vec3& z) const {
        return model_ ? model_->ray(raster, z) : generateRay(raster);
    }
    // Where the point p, seen from camera point z, lands on the image.
    bool rasterPosition(const Vec3& z, const Vec3& p, Vec2& raster) const {
        return model_ ? model_->rasterOfDirection(z, p - z, raster) : rasterPosition(p, raster);
    }
    // Where the ray (z, dir) (dir of any length) lands on the image.
    bool rasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const {
        return model_ ? model_->rasterOfDirection(z, dir, raster) : rasterOfDirection(dir, raster);
    }
    // W_e(z, dir) and the solid-angle pdf of dir at z.
    float We(const Vec3& z, const Vec3& dir) const { return model_ ? model_->We(z, dir) : We(dir); }
    float pdfDirection(const Vec3& z, const Vec3& dir) const {
        return model_ ? model_->pdfDirection(z, dir) : pdfDirection(dir);
    }
    // Where a ray meets the camera's points (the distance t in (0, ray.tMax), the point z): never
    // for the pinhole.
    bool hit(const Ray& ray, float& t, Vec3& z) const { return model_ && model_->hit(ray, t, z); }

    // The framework's pixel loop's ray through raster position `raster` (tasks.h, cameraRay): the
    // pinhole's, or the model's through its point for u.
    Ray sampleRay(const Vec2& raster, const Vec2& u) const {
        return model_ ? model_->ray(raster, model_->samplePoint(u)) : generateRay(raster);
    }

private:
    Vec3 eye_, forward_ = Vec3(0, 0, 1), right_ = Vec3(1, 0, 0), up_ = Vec3(0, 1, 0);
    float tanHalfX_ = 1.0f, tanHalfY_ = 1.0f;
    int width_ = 1, height_ = 1;
    std::shared_ptr<const CameraModel> model_;
};

}  // namespace ps
