#include "scene_loader.h"
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#ifdef PATHSPACE_TINYOBJLOADER_FROM_HEADER  // framework/CMakeLists.txt: a libc++ build
#define TINYOBJLOADER_IMPLEMENTATION
#endif
#include <tiny_obj_loader.h>
#include "errors.h"
#include "numbers.h"

namespace ps {

namespace {

// One statement of the scene file: its tokens and where it stands.
struct Statement {
    std::string file;
    int line = 0;
    std::vector<std::string> tokens;
    size_t pos = 0;                                           // next token to read
    std::map<std::string, std::vector<std::string>> options;  // key -> its values

    [[noreturn]] void fail(const std::string& problem) const { throw InputError(file, line, problem); }
    std::string keyword() const { return tokens[0]; }

    std::string word(const std::string& what) {
        if (pos >= tokens.size()) fail("'" + keyword() + "' needs " + what);
        return tokens[pos++];
    }
    static float toFloat(const Statement& st, const std::string& tok, const std::string& what) {
        float v = 0.0f;
        const std::errc ec = parseWhole(tok, v);
        if (ec == std::errc::result_out_of_range)
            st.fail("number '" + tok + "' for " + what + " is out of range (beyond float)");
        if (ec != std::errc()) st.fail("malformed number '" + tok + "' for " + what);
        if (!std::isfinite(v)) st.fail("'" + tok + "' for " + what + " is not a finite number");
        return v;
    }
    static int toInt(const Statement& st, const std::string& tok, const std::string& what) {
        int v = 0;
        auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
        if (ec != std::errc() || end != tok.data() + tok.size()) st.fail("malformed integer '" + tok + "' for " + what);
        return v;
    }
    float number(const std::string& what) { return toFloat(*this, word(what), what); }
    Vec3 vec3(const std::string& what) {
        float x = number(what);
        float y = number(what);
        return Vec3(x, y, number(what));
    }

    // Reads "key value..." pairs to the end of the line; arity gives each allowed key's count.
    void readOptions(const std::map<std::string, int>& arity) {
        while (pos < tokens.size()) {
            const std::string key = tokens[pos++];
            auto it = arity.find(key);
            if (it == arity.end()) {
                std::string allowed;
                for (const auto& [k, n] : arity) allowed += (allowed.empty() ? "" : ", ") + k;
                fail("unknown option '" + key + "' for '" + keyword() + "' (expected: " + allowed + ")");
            }
            if (options.count(key)) fail("option '" + key + "' given twice");
            std::vector<std::string> values;
            for (int i = 0; i < it->second; ++i) {
                // Too few values: the line ends, or (for numeric options) the next option's name comes.
                const bool nextKey =
                    pos < tokens.size() && key != "material" && key != "algo" && arity.count(tokens[pos]) > 0;
                if (pos >= tokens.size() || nextKey)
                    fail("option '" + key + "' needs " + std::to_string(it->second) + " value(s), got " +
                         std::to_string(i) + (nextKey ? " before '" + tokens[pos] + "'" : ""));
                values.push_back(tokens[pos++]);
            }
            options[key] = values;
        }
    }
    bool has(const std::string& key) const { return options.count(key) > 0; }
    void require(const std::string& key) const {
        if (!has(key)) fail("'" + keyword() + "' needs the option '" + key + "'");
    }
    float optNumber(const std::string& key, float def) const {
        return has(key) ? toFloat(*this, options.at(key)[0], "'" + key + "'") : def;
    }
    Vec3 optVec3(const std::string& key, const Vec3& def) const {
        if (!has(key)) return def;
        const auto& v = options.at(key);
        const std::string what = "'" + key + "'";
        return Vec3(toFloat(*this, v[0], what), toFloat(*this, v[1], what), toFloat(*this, v[2], what));
    }
    int optInt(const std::string& key, int def) const {
        return has(key) ? toInt(*this, options.at(key)[0], "'" + key + "'") : def;
    }
    std::string optWord(const std::string& key, const std::string& def) const {
        return has(key) ? options.at(key)[0] : def;
    }
};

// tinyobjloader's multi-line messages as one line.
std::string oneLine(std::string msg) {
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r' || msg.back() == ' ')) msg.pop_back();
    for (size_t i; (i = msg.find('\n')) != std::string::npos;) msg.replace(i, 1, "; ");
    return msg;
}

// The words of one line of an OBJ or MTL file, '#' comments left out.
std::vector<std::string> tokensOf(std::string line) {
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    std::vector<std::string> tok;
    for (std::string t; ls >> t;) tok.push_back(t);
    return tok;
}

std::string folderOf(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool isDegenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    // In double: at coordinates near 1e15 and beyond, the squares of float lengths overflow and
    // a large triangle would look degenerate.
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
    const double l = glm::length(e1) * glm::length(e2);
    // Zero area, or so thin that its normal is meaningless (sin of the angle below 1e-6).
    return !(l > 0.0) || !(glm::length(glm::cross(e1, e2)) > 1e-6 * l);
}

// The unit normal of the triangle (a, b, c), in double (see isDegenerate).
glm::dvec3 unitNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::normalize(glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a)));
}

// Radiance, intensity and emission values above this leave no room in float for the products
// of light transport (radiance x area x pi, Le / pdf, ...): an overflow would show up as a black
// or Inf image long after loading.
constexpr float kMaxEmission = 1e30f;

// The largest Phong exponent: a lobe of exponent n is about 1/sqrt(n) radians wide, and float
// directions near the mirror direction resolve cos(theta) only to ~6e-8, i.e. angles of ~3e-4
// radians; beyond 1e7 the lobe is narrower than that (use a mirror).
constexpr float kMaxPhongExponent = 1e7f;

// Input files are read whole: a scene file, an OBJ or MTL larger than these (or a device such as
// /dev/zero, which never ends) is refused before reading.
constexpr uint64_t kMaxSceneBytes = uint64_t(64) << 20;
constexpr uint64_t kMaxMeshBytes = uint64_t(1) << 30;

template <class Fail>
void checkFileSize(const std::string& path, uint64_t limit, const Fail& fail) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        fail("'" + path + "' is not a regular file (a folder or a device cannot be read as one)");
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > limit)
        fail("'" + path + "' has " + std::to_string(size >> 20) + " MiB; at most " + std::to_string(limit >> 20) +
             " MiB are read");
}

Color checkColor(const Statement& st, const std::string& key, const Color& c, bool atMostOne) {
    if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) st.fail("'" + key + "' must not be negative");
    if (maxComponent(c) > kMaxEmission)
        st.fail("'" + key +
                "' above 1e30: light transport multiplies it by areas, pdfs and cosines in float, "
                "which would overflow (scale the scene's units instead)");
    if (atMostOne && (c.r > 1.0f || c.g > 1.0f || c.b > 1.0f))
        st.fail("'" + key + "' must be at most 1 (a surface cannot reflect more than it receives)");
    return c;
}

class Loader {
public:
    Loader(Scene& scene, const std::string& path) : scene_(scene), path_(path) {}

    void run(std::string text) {
        // A UTF-8 byte order mark (some editors write one) is not part of the first keyword.
        if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        std::istringstream in(text);
        std::string raw;
        int lineNo = 0;
        while (std::getline(in, raw)) {
            ++lineNo;
            if (raw.find('\0') != std::string::npos)
                throw InputError(path_, lineNo, "the line holds a NUL byte: is this a binary file, not a scene file?");
            if (size_t hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
            Statement st;
            st.file = path_;
            st.line = lineNo;
            std::istringstream ls(raw);
            for (std::string tok; ls >> tok;) st.tokens.push_back(tok);
            if (st.tokens.empty()) continue;
            st.pos = 1;
            statement(st);
        }
        if (!haveCamera_) throw InputError(path_, 0, "no 'camera' line: every scene needs a camera");
    }

private:
    void statement(Statement& st) {
        const std::string& k = st.tokens[0];
        if (k == "camera") camera(st);
        else if (k == "material") material(st);
        else if (k == "sphere") sphere(st);
        else if (k == "triangle") polygon(st, 3);
        else if (k == "quad") polygon(st, 4);
        else if (k == "mesh") mesh(st);
        else if (k == "pointlight") pointLight(st);
        else if (k == "background") background(st);
        else if (k == "render") render(st);
        else
            st.fail("unknown keyword '" + k +
                    "' (expected one of: camera, material, sphere, triangle, quad, "
                    "mesh, pointlight, background, render)");
    }

    void camera(Statement& st) {
        if (haveCamera_) st.fail("a second 'camera': a scene has one camera");
        // The pinhole's keywords, and those of every registered camera model (camera.h).
        std::map<std::string, int> arity = {{"eye", 3}, {"target", 3}, {"up", 3}, {"fov", 1}, {"resolution", 2}};
        for (const auto& model : Registry<CameraModelType>::inOrder())
            for (const auto& [key, n] : model.value.keywords) arity[key] = n;
        st.readOptions(arity);
        for (const char* key : {"eye", "target", "fov", "resolution"}) st.require(key);
        const Vec3 eye = st.optVec3("eye", Vec3()), target = st.optVec3("target", Vec3());
        const Vec3 up = st.optVec3("up", Vec3(0, 1, 0));
        const float fov = st.optNumber("fov", 0.0f);
        const auto& res = st.options.at("resolution");
        const int w = Statement::toInt(st, res[0], "'resolution' (width)");
        const int h = Statement::toInt(st, res[1], "'resolution' (height)");
        if (!(fov > 0.0f && fov < 180.0f))
            st.fail("'fov' must be between 0 and 180 degrees (exclusive), got " + st.options.at("fov")[0]);
        if (w < 1 || h < 1 || w > kMaxResolution || h > kMaxResolution)
            st.fail("'resolution' must be between 1 and " + std::to_string(kMaxResolution) +
                    " pixels in each direction, got " + res[0] + " " + res[1]);
        if (static_cast<long long>(w) * h > kMaxPixels)
            st.fail("'resolution' " + res[0] + " " + res[1] + " is " + std::to_string(static_cast<long long>(w) * h) +
                    " pixels, more than the " + std::to_string(kMaxPixels) +
                    " (2048 x 2048) a render may have: some algorithms keep 750 bytes per pixel, and the largest "
                    "image must fit in 4 GiB (scenes/README.md, 'Memory')");
        if (!(glm::length(target - eye) > 0.0f)) st.fail("'eye' and 'target' are the same point");
        const Vec3 f = glm::normalize(target - eye);
        if (!(glm::length(glm::cross(f, up)) > 1e-6f * glm::length(up)))
            st.fail("'up' is parallel to the view direction");
        scene_.camera = Camera(eye, target, up, fov, w, h);
        // A camera model: the one whose keywords the line has (none: the pinhole).
        CameraModelArgs args;
        args.targetDistance = glm::length(target - eye);
        args.has = [&](const std::string& key) { return st.has(key); };
        args.number = [&](const std::string& key, float def) { return st.optNumber(key, def); };
        args.text = [&](const std::string& key) { return st.has(key) ? st.options.at(key)[0] : std::string(); };
        args.fail = [&](const std::string& problem) { st.fail(problem); };
        std::string selected;
        for (const auto& model : Registry<CameraModelType>::inOrder()) {
            bool given = false;
            for (const auto& kw : model.value.keywords) given = given || st.has(kw.first);
            if (!given) continue;
            if (!selected.empty()) st.fail("two camera models: '" + selected + "' and '" + model.name + "'");
            selected = model.name;
            scene_.camera.setModel(model.value.make(scene_.camera, args));
        }
        scene_.camera.line = st.line;
        haveCamera_ = true;
    }

    void material(Statement& st) {
        const std::string name = st.word("a name");
        const std::string type = st.word("a type (diffuse, phong, mirror, dielectric)");
        if (name[0] == '(') st.fail("material name '" + name + "': names starting with '(' are the loader's own");
        if (materialIndex_.count(name))
            st.fail("material '" + name + "' is defined twice (first on line " + std::to_string(materialLine_[name]) +
                    ")");
        materialLine_[name] = st.line;
        Material m;
        m.name = name;
        if (type == "diffuse") {
            st.readOptions({{"albedo", 3}});
            st.require("albedo");
            m.kind = BSDFKind::Diffuse;
        } else if (type == "phong") {
            st.readOptions({{"albedo", 3}, {"exponent", 1}});
            st.require("albedo");
            st.require("exponent");
            m.kind = BSDFKind::Phong;
            m.exponent = st.optNumber("exponent", 0.0f);
            if (m.exponent < 0.0f) st.fail("'exponent' must not be negative");
            if (m.exponent > kMaxPhongExponent)
                st.fail(
                    "'exponent' above 1e7: the lobe would be narrower than float directions can resolve "
                    "(use 'mirror' for a perfect reflector)");
        } else if (type == "mirror") {
            st.readOptions({{"albedo", 3}});
            m.kind = BSDFKind::Mirror;
        } else if (type == "dielectric") {
            st.readOptions({{"ior", 1}});
            st.require("ior");
            m.kind = BSDFKind::Dielectric;
            m.ior = st.optNumber("ior", 1.5f);
            if (!(m.ior > 0.0f)) st.fail("'ior' must be positive");
        } else {
            st.fail("unknown material type '" + type + "' (expected: diffuse, phong, mirror, dielectric)");
        }
        m.albedo = checkColor(st, "albedo", st.optVec3("albedo", Color(1.0f)), true);
        materialIndex_[name] = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(m);
    }

    // The material of a shape, and its light if it has "emission".
    void shapeMaterial(const Statement& st, int& material, int& light) {
        light = -1;
        if (st.has("emission")) {
            const Color Le = checkColor(st, "emission", st.optVec3("emission", Color(0.0f)), false);
            if (!isBlack(Le)) {
                Light l;
                l.kind = LightKind::Area;
                l.Le = Le;
                l.line = st.line;
                light = static_cast<int>(scene_.lights.size());
                scene_.lights.push_back(l);
            }
        }
        if (!st.has("material")) {
            if (!st.has("emission")) st.fail("'" + st.keyword() + "' needs the option 'material'");
            material = blackMaterial();
            return;
        }
        material = lookupMaterial(st, st.options.at("material")[0]);
    }

    int lookupMaterial(const Statement& st, const std::string& name) {
        auto it = materialIndex_.find(name);
        if (it == materialIndex_.end()) {
            std::string known;
            for (const auto& [n, i] : materialIndex_) known += (known.empty() ? "" : ", ") + n;
            st.fail("unknown material '" + name + "' (defined so far: " + (known.empty() ? "none" : known) + ")");
        }
        return it->second;
    }

    int blackMaterial() {
        const std::string name = "(emitter)";
        if (!materialIndex_.count(name)) {
            Material m;
            m.name = name;
            m.albedo = Color(0.0f);
            materialIndex_[name] = static_cast<int>(scene_.materials.size());
            scene_.materials.push_back(m);
        }
        return materialIndex_[name];
    }

    void addTriangle(const Triangle& t, int material, int light) {
        Primitive p;
        p.shape = ShapeKind::Triangle;
        p.index = static_cast<uint32_t>(scene_.triangles.size());
        p.material = material;
        p.light = light;
        if (light >= 0) scene_.lights[light].prims.push_back(static_cast<uint32_t>(scene_.prims.size()));
        scene_.triangles.push_back(t);
        scene_.prims.push_back(p);
    }

    void sphere(Statement& st) {
        st.readOptions({{"center", 3}, {"radius", 1}, {"material", 1}, {"emission", 3}});
        st.require("center");
        st.require("radius");
        Sphere s;
        s.center = st.optVec3("center", Vec3());
        s.radius = st.optNumber("radius", 0.0f);
        if (s.radius < 0.0f)
            st.fail("negative radius " + st.options.at("radius")[0] + " (a sphere's radius must be positive)");
        if (!(s.radius > 0.0f)) st.fail("'radius' must be positive");
        // Float resolves the sphere's points only to the spacing of its centre's coordinates: a
        // radius of a few such steps is no sphere any more (hits and shadow rays on it are noise).
        const float step = std::nextafter(maxAbsComponent(s.center), kInf) - maxAbsComponent(s.center);
        if (s.radius < 16.0f * step)
            st.fail("radius " + st.options.at("radius")[0] + " is below 16 float steps (" + std::to_string(step) +
                    ") of its centre's coordinates: float cannot resolve such a sphere there (move it closer to "
                    "the origin or scale the scene)");
        int material, light;
        shapeMaterial(st, material, light);
        Primitive p;
        p.shape = ShapeKind::Sphere;
        p.index = static_cast<uint32_t>(scene_.spheres.size());
        p.material = material;
        p.light = light;
        if (light >= 0) scene_.lights[light].prims.push_back(static_cast<uint32_t>(scene_.prims.size()));
        scene_.spheres.push_back(s);
        scene_.prims.push_back(p);
    }

    // "triangle x y z  x y z  x y z options" or "quad" with four corners (counter-clockwise
    // seen from the side the normal points to; a quad is split into (0,1,2) and (0,2,3)).
    void polygon(Statement& st, int corners) {
        std::vector<Vec3> v;
        for (int i = 0; i < corners; ++i) v.push_back(st.vec3("corner " + std::to_string(i + 1) + " (x y z)"));
        st.readOptions({{"material", 1}, {"emission", 3}});
        int material, light;
        shapeMaterial(st, material, light);
        for (int i = 1; i + 1 < corners; ++i) {
            if (isDegenerate(v[0], v[i], v[i + 1]))
                st.fail(corners == 3
                            ? std::string("degenerate triangle: its corners coincide or lie on a line (zero area)")
                            : "degenerate quad: corners 1, " + std::to_string(i + 1) + ", " + std::to_string(i + 2) +
                                  " coincide or lie on a line (zero area)");
        }
        // The halves (1,2,3) and (1,3,4) of a quad must face the same way; they do not if the
        // corners are not in order around the quad (a bow tie) or it is concave at corner 2 or 4.
        if (corners == 4 && glm::dot(unitNormal(v[0], v[1], v[2]), unitNormal(v[0], v[2], v[3])) <= 0.0)
            st.fail(
                "the quad's halves (corners 1-2-3 and 1-3-4) face opposite ways: its corners are not in order "
                "around its edge, or it is concave at corner 2 or 4 (start at the concave corner)");
        if (corners == 4) {  // the record of the quad (Scene::Quad)
            Quad q;
            for (int i = 0; i < 4; ++i) q.corners[i] = v[size_t(i)];
            q.prim = static_cast<uint32_t>(scene_.prims.size());
            q.line = st.line;
            scene_.quads.push_back(q);
        }
        for (int i = 1; i + 1 < corners; ++i) addTriangle({v[0], v[i], v[i + 1]}, material, light);
    }

    void mesh(Statement& st) {
        const std::string file = st.word("a file name (an OBJ mesh)");
        st.readOptions({{"material", 1}, {"emission", 3}, {"scale", 1}, {"translate", 3}});
        const float scale = st.optNumber("scale", 1.0f);
        if (!(scale > 0.0f)) st.fail("'scale' must be positive");
        const Vec3 translate = st.optVec3("translate", Vec3(0.0f));
        const std::string objPath = (!file.empty() && file[0] == '/') ? file : folderOf(path_) + file;
        if (!std::ifstream(objPath)) st.fail("cannot open mesh file '" + objPath + "'");
        checkFileSize(objPath, kMaxMeshBytes, [&](const std::string& problem) { st.fail(problem); });
        const std::string meshOf = " (mesh of " + path_ + ":" + std::to_string(st.line) + ")";
        // Our own pass first: tinyobjloader reads malformed numbers as 0 and drops short faces
        // without a word; this reports them, and gives each face its line for later messages.
        scene_.inputFiles.push_back(objPath);
        const std::vector<int> faceLines = scanObj(objPath, meshOf, scene_.inputFiles);

        tinyobj::attrib_t attrib;
        std::vector<tinyobj::shape_t> shapes;
        std::vector<tinyobj::material_t> mtls;
        std::string warn, err;
        const bool ok = tinyobj::LoadObj(&attrib, &shapes, &mtls, &warn, &err, objPath.c_str(),
                                         folderOf(objPath).c_str(), /*triangulate=*/false);
        if (!ok || !err.empty()) {
            throw InputError(objPath, 0, "cannot read OBJ: " + oneLine(err.empty() ? warn : err) + meshOf);
        }
        warn = oneLine(warn);
        auto objFail = [&](size_t face, const std::string& problem) {
            const int line = face < faceLines.size() ? faceLines[face] : 0;
            throw InputError(objPath, line, problem + meshOf);
        };

        // The scene's material and emission, or, without 'material', the MTL's Kd and Ke.
        int sceneMaterial = -1, sceneLight = -1;
        if (st.has("material") || st.has("emission")) shapeMaterial(st, sceneMaterial, sceneLight);
        std::map<int, std::pair<int, int>> fromMtl;  // MTL id -> (material, light)
        auto mtlMaterial = [&](int id, size_t face) -> std::pair<int, int> {
            if (sceneMaterial >= 0) return {sceneMaterial, sceneLight};
            if (id < 0 || id >= static_cast<int>(mtls.size()))
                objFail(face, "face has no material: give the mesh a 'material' in the scene, or the OBJ an MTL file" +
                                  (warn.empty() ? std::string() : " [tinyobjloader: " + warn + "]"));
            auto it = fromMtl.find(id);
            if (it != fromMtl.end()) return it->second;
            const tinyobj::material_t& tm = mtls[id];
            Material m;
            m.name = file + ":" + tm.name;
            m.kind = BSDFKind::Diffuse;
            // Kd is in [0, 1] (scanMtl refuses anything else); the clamp only guards against a
            // reading of tinyobjloader's that differs from ours.
            m.albedo = glm::clamp(Color(tm.diffuse[0], tm.diffuse[1], tm.diffuse[2]), 0.0f, 1.0f);
            const int mi = static_cast<int>(scene_.materials.size());
            scene_.materials.push_back(m);
            int li = -1;
            const Color Ke(tm.emission[0], tm.emission[1], tm.emission[2]);
            if (isFinite(Ke) && maxComponent(Ke) > 0.0f) {
                Light l;
                l.kind = LightKind::Area;
                l.Le = glm::max(Ke, Color(0.0f));
                li = static_cast<int>(scene_.lights.size());
                scene_.lights.push_back(l);
            }
            return fromMtl[id] = {mi, li};
        };

        const size_t nVerts = attrib.vertices.size() / 3;
        for (float c : attrib.vertices)
            if (!std::isfinite(c)) throw InputError(objPath, 0, "vertex coordinate is not a finite number");
        size_t face = 0, added = 0;
        for (const tinyobj::shape_t& shape : shapes) {
            size_t idx = 0;
            for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
                const int n = shape.mesh.num_face_vertices[f];
                if (n < 3) objFail(face, "face with " + std::to_string(n) + " vertices (a face needs at least 3)");
                std::vector<Vec3> v;
                for (int k = 0; k < n; ++k) {
                    const int vi = shape.mesh.indices[idx + k].vertex_index;
                    if (vi < 0)
                        objFail(face, "relative vertex index points before the first vertex (the file has " +
                                          std::to_string(nVerts) + " vertices)");
                    if (static_cast<size_t>(vi) >= nVerts)
                        objFail(face, "vertex index " + std::to_string(vi + 1) + " out of range (the file has " +
                                          std::to_string(nVerts) + " vertices)");
                    v.push_back(
                        Vec3(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]) *
                            scale +
                        translate);
                }
                idx += n;
                const int mtlId = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
                const auto [material, light] = mtlMaterial(mtlId, face);
                for (int k = 1; k + 1 < n; ++k) {  // fan triangulation
                    if (isDegenerate(v[0], v[k], v[k + 1]))
                        objFail(face, "degenerate face: its corners coincide or lie on a line (zero area)");
                    addTriangle({v[0], v[k], v[k + 1]}, material, light);
                    ++added;
                }
            }
        }
        if (added == 0) throw InputError(objPath, 0, "empty mesh: no faces" + meshOf);
    }

    // Checks what tinyobjloader lets pass (a 'v' line's numbers, a face's vertex count and
    // indices) and returns the line numbers of the OBJ's faces, in order, for later messages.
    // The material libraries it names are added to `files`.
    static std::vector<int> scanObj(const std::string& objPath, const std::string& meshOf,
                                    std::vector<std::string>& files) {
        std::vector<int> lines;
        std::ifstream in(objPath);
        std::string s;
        for (int n = 1; std::getline(in, s); ++n) {
            const std::vector<std::string> tok = tokensOf(s);
            if (tok.empty()) continue;
            auto fail = [&](const std::string& problem) { throw InputError(objPath, n, problem + meshOf); };
            if (tok[0] == "v") {
                if (tok.size() < 4)
                    fail("vertex with " + std::to_string(tok.size() - 1) + " coordinates (needs x y z)");
                for (size_t k = 1; k < 4; ++k) {
                    float x = 0.0f;
                    if (parseWhole(tok[k], x) != std::errc() || !std::isfinite(x))
                        fail("malformed or non-finite vertex coordinate '" + tok[k] + "'");
                }
            } else if (tok[0] == "mtllib") {
                for (size_t k = 1; k < tok.size(); ++k) {
                    files.push_back(folderOf(objPath) + tok[k]);
                    scanMtl(files.back(), " (material library of " + objPath + ")" + meshOf);
                }
            } else if (tok[0] == "f") {
                if (tok.size() < 4)
                    fail("face with " + std::to_string(tok.size() - 1) + " vertices (a face needs at least 3)");
                if (tok.size() - 1 > 255)  // tinyobjloader keeps a face's corner count in one byte
                    fail("face with " + std::to_string(tok.size() - 1) +
                         " corners: at most 255 are supported (split it into smaller faces)");
                for (size_t k = 1; k < tok.size(); ++k) {
                    const std::string idx = tok[k].substr(0, tok[k].find('/'));
                    int i = 0;
                    auto [end, ec] = std::from_chars(idx.data(), idx.data() + idx.size(), i);
                    if (ec != std::errc() || end != idx.data() + idx.size() || i == 0)
                        fail("malformed vertex index '" + tok[k] + "' (OBJ indices are 1, 2, ... or -1, -2, ...)");
                }
                lines.push_back(n);
            }
        }
        return lines;
    }

    // Checks what tinyobjloader lets pass in an MTL file: the Kd and Ke values pathspace reads
    // must be three finite, non-negative numbers (tinyobjloader reads "abc" as 0 and accepts
    // "nan"), Kd at most 1, Ke at most 1e30. A missing MTL file is tinyobjloader's to report.
    static void scanMtl(const std::string& mtlPath, const std::string& meshOf) {
        std::ifstream in(mtlPath);
        if (!in) return;
        checkFileSize(mtlPath, kMaxMeshBytes,
                      [&](const std::string& problem) { throw InputError(mtlPath, 0, problem + meshOf); });
        std::string s;
        for (int n = 1; std::getline(in, s); ++n) {
            const std::vector<std::string> tok = tokensOf(s);
            if (tok.empty() || (tok[0] != "Kd" && tok[0] != "Ke")) continue;
            auto fail = [&](const std::string& problem) { throw InputError(mtlPath, n, problem + meshOf); };
            if (tok.size() != 4)
                fail("'" + tok[0] + "' needs three numbers (r g b), got " + std::to_string(tok.size() - 1));
            for (size_t k = 1; k < 4; ++k) {
                float x = 0.0f;
                if (parseWhole(tok[k], x) != std::errc() || !std::isfinite(x))
                    fail("malformed or non-finite number '" + tok[k] + "' in '" + tok[0] + "'");
                if (x < 0.0f) fail("'" + tok[0] + "' must not be negative, got " + tok[k]);
                if (tok[0] == "Kd" && x > 1.0f)
                    fail("'Kd' must be at most 1 (a surface cannot reflect more than it receives), got " + tok[k]);
                if (tok[0] == "Ke" && x > kMaxEmission)
                    fail("'Ke' above 1e30: light transport in float would overflow (scale the units instead)");
            }
        }
    }

    void pointLight(Statement& st) {
        st.readOptions({{"position", 3}, {"intensity", 3}});
        st.require("position");
        st.require("intensity");
        Light l;
        l.kind = LightKind::Point;
        l.line = st.line;
        l.position = st.optVec3("position", Vec3());
        l.Le = checkColor(st, "intensity", st.optVec3("intensity", Color(0.0f)), false);
        scene_.lights.push_back(l);
    }

    void background(Statement& st) {
        if (haveBackground_) st.fail("a second 'background': a scene has at most one");
        st.readOptions({{"radiance", 3}});
        st.require("radiance");
        Light l;
        l.kind = LightKind::Background;
        l.line = st.line;
        l.Le = checkColor(st, "radiance", st.optVec3("radiance", Color(0.0f)), false);
        scene_.lights.push_back(l);
        haveBackground_ = true;
    }

    void render(Statement& st) {
        const std::map<std::string, int> own{{"spp", 1}, {"maxdepth", 1}, {"algo", 1}};  // never a lesson's
        std::map<std::string, int> arity = own;
        for (const auto& p : Registry<RenderParameter>::sorted())
            if (!own.count(p.name)) arity[p.name] = p.value.count;
        st.readOptions(arity);
        RenderSettings& s = scene_.settings;
        for (const auto& p : Registry<RenderParameter>::sorted()) {
            if (own.count(p.name) || !st.has(p.name)) continue;
            std::vector<float> values;  // each a finite number (toFloat), their count from arity
            for (const std::string& v : st.options.at(p.name))
                values.push_back(Statement::toFloat(st, v, "'" + p.name + "'"));
            const std::string problem = renderParameterProblem(p.value, values);
            if (!problem.empty()) {
                std::string got;
                for (const std::string& v : st.options.at(p.name)) got += (got.empty() ? "" : " ") + v;
                st.fail("'" + p.name + "' " + problem + ", got " + got);
            }
            s.parameters[p.name] = values;
        }
        s.spp = st.optInt("spp", s.spp);
        s.maxDepth = st.optInt("maxdepth", s.maxDepth);
        s.algo = st.optWord("algo", s.algo);
        if (st.has("algo")) s.algoLine = st.line;
        if (s.spp < 1) st.fail("'spp' must be at least 1");
        if (s.maxDepth < 0) st.fail("'maxdepth' must not be negative");
    }

    Scene& scene_;
    std::string path_;
    std::map<std::string, int> materialIndex_;
    std::map<std::string, int> materialLine_;  // where each material of the scene file is defined
    bool haveCamera_ = false, haveBackground_ = false;
};

}  // namespace

Scene parseScene(const std::string& text, const std::string& path) {
    Scene scene;
    scene.path = path;
    scene.inputFiles = {path};
    Loader(scene, path).run(text);
    scene.finalize();
    return scene;
}

Scene loadScene(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path, 0, "cannot open scene file (does it exist?)");
    checkFileSize(path, kMaxSceneBytes, [&](const std::string& problem) { throw InputError(path, 0, problem); });
    std::ostringstream ss;
    ss << in.rdbuf();
    Scene scene = parseScene(ss.str(), path);
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "pathspace: warning: %s: %s\n", path.c_str(), w.c_str());
    return scene;
}

}  // namespace ps
