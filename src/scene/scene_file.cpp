#include "scene/scene_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <sstream>

#include "base/input_file.h"
#include "scene/presets.h"

namespace pcf {

namespace {

// A value in a message, as the file gave it: the shortest text that reads back as the same
// double, never rounded to a limit it exceeds ("got 89.0000000001", not "got 89").
std::string formatNumber(double v) { return exactNumberText(v); }

template <int N>
std::string formatVector(const glm::vec<N, double>& v) {
    std::string out = "[";
    for (int i = 0; i < N; ++i) out += (i ? ", " : "") + formatNumber(v[i]);
    return out + "]";
}

std::string typeName(const toml::node& node) {
    std::ostringstream s;
    s << node.type();
    return s.str();
}

// Reads one table (camera, light, an object) and reports problems against the right line.
// `what` starts every message: "camera", "light", "spot light", "sphere".
class TableReader {
  public:
    TableReader(const std::string& source, const toml::table& table, std::string what)
        : mSource(source), mTable(table), mWhat(std::move(what)) {}

    [[noreturn]] void fail(const toml::node* node, const std::string& problem) const {
        const toml::node& at = node ? *node : static_cast<const toml::node&>(mTable);
        throw InputError(mSource, lineOf(at), problem);
    }

    static int lineOf(const toml::node& node) {
        return std::max(1, static_cast<int>(node.source().begin.line));
    }

    const toml::node* find(std::string_view key) const { return mTable.get(key); }

    const toml::node& require(std::string_view key) const {
        const toml::node* node = mTable.get(key);
        if (!node) fail(nullptr, mWhat + " is missing required key '" + std::string(key) + "'");
        return *node;
    }

    // Refuses keys outside `allowed`: a misspelt key would otherwise be silently ignored.
    void checkKeys(std::initializer_list<std::string_view> allowed) const {
        for (auto&& [key, value] : mTable) {
            bool known = false;
            for (std::string_view a : allowed) known = known || key.str() == a;
            if (known) continue;
            std::string problem = mWhat + " has unknown key '" + std::string(key.str()) + "'";
            if (key.str() == "color") problem += " (did you mean 'colour'?)";
            if (key.str() == "center") problem += " (did you mean 'centre'?)";
            throw InputError(mSource, std::max(1, static_cast<int>(key.source().begin.line)),
                             problem);
        }
    }

    double number(const toml::node& node, const std::string& name) const {
        double v;
        if (const auto* i = node.as_integer()) {
            v = static_cast<double>(i->get());
        } else if (const auto* f = node.as_floating_point()) {
            v = f->get();
        } else {
            fail(&node, mWhat + " " + name + " must be a number, got " + typeName(node));
        }
        if (!std::isfinite(v)) {
            fail(&node, mWhat + " " + name + " must be finite, got " + formatNumber(v));
        }
        // Scenes are computed in float: a radius of 1e301 became infinity and no camera planes
        // could be fitted. Scenes are metres across; 1e6 leaves squares (1e12) well inside float.
        if (std::abs(v) > MAX_SCENE_NUMBER) {
            fail(&node, mWhat + " " + name + " must be within +-" + formatNumber(MAX_SCENE_NUMBER) +
                            ", got " + formatNumber(v));
        }
        return v;
    }

    double number(std::string_view key) const { return number(require(key), std::string(key)); }

    std::optional<double> optionalNumber(std::string_view key) const {
        const toml::node* node = find(key);
        if (!node) return std::nullopt;
        return number(*node, std::string(key));
    }

    template <int N>
    glm::vec<N, double> vector(const toml::node& node, std::string_view key) const {
        const toml::array* array = node.as_array();
        std::string name(key);
        std::string shape = "an array of " + std::to_string(N) + " numbers";
        if (!array)
            fail(&node, mWhat + " " + name + " must be " + shape + ", got " + typeName(node));
        if (array->size() != static_cast<size_t>(N)) {
            fail(&node, mWhat + " " + name + " must be " + shape + ", got " +
                            std::to_string(array->size()));
        }
        glm::vec<N, double> v;
        for (int i = 0; i < N; ++i) {
            v[i] =
                number(*array->get(static_cast<size_t>(i)), name + "[" + std::to_string(i) + "]");
        }
        return v;
    }

    template <int N>
    glm::vec<N, double> vector(std::string_view key) const {
        return vector<N>(require(key), key);
    }

    std::string string(const toml::node& node, std::string_view key) const {
        const auto* s = node.as_string();
        if (!s) {
            fail(&node,
                 mWhat + " " + std::string(key) + " must be a string, got " + typeName(node));
        }
        return s->get();
    }

    bool boolean(std::string_view key, bool fallback) const {
        const toml::node* node = find(key);
        if (!node) return fallback;
        const auto* b = node->as_boolean();
        if (!b) {
            fail(node,
                 mWhat + " " + std::string(key) + " must be true or false, got " + typeName(*node));
        }
        return b->get();
    }

    // A direction: not zero-length; returned unit.
    glm::dvec3 direction(std::string_view key) const {
        const toml::node& node = require(key);
        glm::dvec3 v = vector<3>(node, key);
        double len = glm::length(v);
        if (!(len > 0.0)) fail(&node, mWhat + " " + std::string(key) + " must not be zero-length");
        return v / len;
    }

    template <int N>
    glm::vec<N, double> positiveVector(std::string_view key) const {
        const toml::node& node = require(key);
        glm::vec<N, double> v = vector<N>(node, key);
        for (int i = 0; i < N; ++i) {
            if (!(v[i] > 0.0)) {
                fail(&node,
                     mWhat + " " + std::string(key) + " must be positive, got " + formatVector(v));
            }
        }
        return v;
    }

    double positive(std::string_view key) const {
        const toml::node& node = require(key);
        double v = number(node, std::string(key));
        if (!(v > 0.0)) {
            fail(&node,
                 mWhat + " " + std::string(key) + " must be positive, got " + formatNumber(v));
        }
        return v;
    }

    const std::string& what() const { return mWhat; }

  private:
    const std::string& mSource;
    const toml::table& mTable;
    std::string mWhat;
};

const toml::table& requireTable(const std::string& source, const toml::table& root,
                                std::string_view key) {
    const toml::node* node = root.get(key);
    if (!node) {
        throw InputError(source, TableReader::lineOf(root),
                         "scene is missing the [" + std::string(key) + "] table");
    }
    const toml::table* table = node->as_table();
    if (!table) {
        throw InputError(source, TableReader::lineOf(*node),
                         std::string(key) + " must be a table ([" + std::string(key) + "]), got " +
                             typeName(*node));
    }
    return *table;
}

Camera readCamera(const std::string& source, const toml::table& table) {
    TableReader r(source, table, "camera");
    r.checkKeys({"eye", "target", "up", "fov", "near", "far"});
    Camera camera;
    glm::dvec3 eye = r.vector<3>("eye");
    const toml::node& targetNode = r.require("target");
    glm::dvec3 target = r.vector<3>(targetNode, "target");
    if (glm::vec3(eye) == glm::vec3(target)) {
        r.fail(&targetNode, "camera eye and target must differ, both are " + formatVector(eye));
    }
    glm::dvec3 up(0.0, 1.0, 0.0);
    if (const toml::node* upNode = r.find("up")) {
        up = r.vector<3>(*upNode, "up");
        double len = glm::length(up);
        if (!(len > 0.0)) r.fail(upNode, "camera up must not be zero-length");
        up /= len;
    }
    glm::dvec3 forward = glm::normalize(target - eye);
    if (glm::length(glm::cross(forward, up)) < 1e-6) {
        r.fail(r.find("up"), "camera up must not be parallel to the view direction (target - eye)");
    }
    if (const toml::node* fovNode = r.find("fov")) {
        double fov = r.number(*fovNode, "fov");
        if (!(fov > 1.0 && fov < 179.0)) {
            r.fail(fovNode, "camera fov must be in (1, 179) degrees, got " + formatNumber(fov));
        }
        camera.fovYDeg = static_cast<float>(fov);
    }
    std::optional<double> nearZ;
    if (const toml::node* nearNode = r.find("near")) {
        nearZ = r.number(*nearNode, "near");
        if (!(*nearZ > 0.0)) {
            r.fail(nearNode, "camera near must be positive, got " + formatNumber(*nearZ));
        }
        camera.nearZ = static_cast<float>(*nearZ);
    }
    if (const toml::node* farNode = r.find("far")) {
        double farZ = r.number(*farNode, "far");
        if (!(farZ > nearZ.value_or(0.0))) {
            r.fail(farNode, "camera far must be greater than near" +
                                std::string(nearZ ? " (" + formatNumber(*nearZ) + ")" : " and 0") +
                                ", got " + formatNumber(farZ));
        }
        camera.farZ = static_cast<float>(farZ);
    }
    camera.eyeWs = glm::vec3(eye);
    camera.targetWs = glm::vec3(target);
    camera.upWs = glm::vec3(up);
    return camera;
}

Light readLight(const std::string& source, const toml::table& table) {
    TableReader typeReader(source, table, "light");
    const toml::node& typeNode = typeReader.require("type");
    std::string type = typeReader.string(typeNode, "type");
    Light light;
    if (type == "directional") {
        TableReader r(source, table, "directional light");
        r.checkKeys({"type", "direction", "angular_diameter"});
        light.type = LightType::Directional;
        light.directionWs = glm::vec3(r.direction("direction"));
        if (const toml::node* sizeNode = r.find("angular_diameter")) {
            double size = r.number(*sizeNode, "angular_diameter");
            // The range of the setting that overrides it (kernel/settings.h light_size).
            if (auto why = paramRangeProblem(*findParam("light_size"), size)) {
                r.fail(sizeNode, why->say("directional light angular_diameter"));
            }
            light.angularDiameterDeg = static_cast<float>(size);
        }
    } else if (type == "spot") {
        TableReader r(source, table, "spot light");
        r.checkKeys({"type", "direction", "position", "cone", "radius"});
        light.type = LightType::Spot;
        light.directionWs = glm::vec3(r.direction("direction"));
        light.positionWs = glm::vec3(r.vector<3>("position"));
        const toml::node& coneNode = r.require("cone");
        double cone = r.number(coneNode, "cone");
        if (!(cone >= MIN_SPOT_CONE_DEG && cone <= MAX_SPOT_CONE_DEG)) {
            r.fail(&coneNode, "spot light cone must be in [" + formatNumber(MIN_SPOT_CONE_DEG) +
                                  ", " + formatNumber(MAX_SPOT_CONE_DEG) + "] degrees, got " +
                                  formatNumber(cone));
        }
        light.coneDeg = static_cast<float>(cone);
        if (const toml::node* radiusNode = r.find("radius")) {
            double radius = r.number(*radiusNode, "radius");
            // The range of the setting that overrides it (kernel/settings.h light_radius).
            if (auto why = paramRangeProblem(*findParam("light_radius"), radius)) {
                r.fail(radiusNode, why->say("spot light radius"));
            }
            light.radius = static_cast<float>(radius);
        }
    } else {
        typeReader.fail(&typeNode,
                        "unknown light type '" + type + "' (expected directional or spot)");
    }
    return light;
}

SceneObject readObject(const std::string& source, const toml::table& table, size_t index) {
    TableReader typeReader(source, table, "object");
    const toml::node& typeNode = typeReader.require("type");
    std::string type = typeReader.string(typeNode, "type");
    TableReader r(source, table, type);
    SceneObject object;
    if (type == "plane") {
        r.checkKeys({"type", "name", "colour", "casts_shadow", "receives_shadow", "centre",
                     "normal", "size", "tangent"});
        glm::dvec3 centre = r.vector<3>("centre");
        glm::dvec3 normal = r.direction("normal");
        glm::dvec2 size = r.positiveVector<2>("size");
        std::optional<glm::vec3> tangent;
        const toml::node* tangentNode = r.find("tangent");
        if (tangentNode) tangent = glm::vec3(r.vector<3>(*tangentNode, "tangent"));
        std::optional<Plane> plane =
            makePlane(glm::vec3(centre), glm::vec3(normal), glm::vec2(size), tangent);
        if (!plane) {
            r.fail(tangentNode, "plane tangent must not be zero-length or parallel to the normal");
        }
        object.shape = *plane;
    } else if (type == "box") {
        r.checkKeys({"type", "name", "colour", "casts_shadow", "receives_shadow", "centre", "half",
                     "rotate_y"});
        Box box;
        box.centreWs = glm::vec3(r.vector<3>("centre"));
        box.halfExtents = glm::vec3(r.positiveVector<3>("half"));
        box.rotateYDeg = static_cast<float>(r.optionalNumber("rotate_y").value_or(0.0));
        object.shape = box;
    } else if (type == "sphere") {
        r.checkKeys(
            {"type", "name", "colour", "casts_shadow", "receives_shadow", "centre", "radius"});
        Sphere sphere;
        sphere.centreWs = glm::vec3(r.vector<3>("centre"));
        sphere.radius = static_cast<float>(r.positive("radius"));
        object.shape = sphere;
    } else {
        typeReader.fail(&typeNode,
                        "unknown object type '" + type + "' (expected plane, box or sphere)");
    }
    if (const toml::node* nameNode = r.find("name")) {
        object.name = r.string(*nameNode, "name");
        if (object.name.empty()) r.fail(nameNode, type + " name must not be empty");
    } else {
        object.name = type + std::to_string(index);
    }
    if (const toml::node* colourNode = r.find("colour")) {
        glm::dvec3 colour = r.vector<3>(*colourNode, "colour");
        if (glm::any(glm::lessThan(colour, glm::dvec3(0.0))) ||
            glm::any(glm::greaterThan(colour, glm::dvec3(1.0)))) {
            r.fail(colourNode, type + " colour must be in [0, 1], got " + formatVector(colour));
        }
        object.colour = glm::vec3(colour);
    }
    object.castsShadow = r.boolean("casts_shadow", true);
    object.receivesShadow = r.boolean("receives_shadow", true);
    return object;
}

// The shortest text that parses back to the same float, always with a '.' or exponent so that
// TOML reads a float.
std::string tomlFloat(float v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), v);
    std::string s(buf, end);
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return s;
}

std::string tomlVec(glm::vec3 v) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on chains of +.
    std::string out = "[";
    for (int i = 0; i < 3; ++i) {
        if (i > 0) out.append(", ");
        out.append(tomlFloat(v[i]));
    }
    out.append("]");
    return out;
}

std::string tomlString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            char esc[8];
            std::snprintf(esc, sizeof(esc), "\\u%04x", static_cast<unsigned>(c));
            out += esc;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

// A scene file that is a preset with its numbers set: [preset] with the preset's name and any
// of its parameters (presets.h), and no other scene table.
Scene readPresetTable(const std::string& source, const toml::table& root,
                      const toml::node& presetNode) {
    const toml::table* table = presetNode.as_table();
    if (!table) {
        throw InputError(source, TableReader::lineOf(presetNode),
                         "preset must be a table ([preset]), got " + typeName(presetNode));
    }
    for (std::string_view other : {"camera", "light", "object"}) {
        if (const toml::node* node = root.get(other)) {
            throw InputError(source, TableReader::lineOf(*node),
                             "a scene file with [preset] takes no " + std::string(other) +
                                 " table (the preset has its own)");
        }
    }
    TableReader r(source, *table, "preset");
    const toml::node& nameNode = r.require("name");
    std::string name = r.string(nameNode, "name");
    if (!presetSceneToml(name)) {
        r.fail(&nameNode, "unknown preset '" + name + "' (known: " + presetNameList() + ")");
    }
    std::span<const PresetParam> params = presetParams(name);
    std::vector<double> values;
    for (const PresetParam& p : params) values.push_back(p.defaultValue);
    for (auto&& [key, node] : *table) {
        if (key.str() == "name") continue;
        size_t i = 0;
        while (i < params.size() && params[i].key != key.str()) ++i;
        if (i == params.size()) {
            std::string known;
            for (const PresetParam& p : params)
                known += (known.empty() ? "" : ", ") + std::string(p.key);
            r.fail(&node, "preset " + name + " has no parameter '" + std::string(key.str()) +
                              "' (it takes " + (known.empty() ? "none" : known) + ")");
        }
        const PresetParam& p = params[i];
        double v = r.number(node, std::string(p.key));
        if (!(v >= p.min && v <= p.max)) {
            r.fail(&node, name + " " + std::string(p.key) + " must be in [" + formatNumber(p.min) +
                              ", " + formatNumber(p.max) + "] " + std::string(p.unit) + ", got " +
                              formatNumber(v));
        }
        values[i] = v;
    }
    Scene scene = *presetScene(name, values);
    scene.name = source;
    return scene;
}

}  // namespace

Scene parseSceneFile(const std::string& path) {
    return parseSceneString(readInputFile(path), path);
}

Scene parseSceneString(std::string_view text, const std::string& sourceName) {
    toml::table root;
    try {
        root = toml::parse(text, sourceName);
    } catch (const toml::parse_error& e) {
        throw InputError(sourceName, std::max(1, static_cast<int>(e.source().begin.line)),
                         std::string(e.description()));
    }
    if (const toml::node* presetNode = root.get("preset")) {
        return readPresetTable(sourceName, root, *presetNode);
    }
    return parseSceneToml(root, sourceName);
}

Scene parseSceneToml(const toml::table& table, const std::string& sourceName) {
    Scene scene;
    scene.name = sourceName;
    scene.camera = readCamera(sourceName, requireTable(sourceName, table, "camera"));
    scene.light = readLight(sourceName, requireTable(sourceName, table, "light"));

    const toml::node* objectsNode = table.get("object");
    if (!objectsNode) {
        throw InputError(sourceName, TableReader::lineOf(table),
                         "scene has no objects: add at least one [[object]] table");
    }
    const toml::array* objects = objectsNode->as_array();
    if (objects && objects->empty()) {
        throw InputError(sourceName, TableReader::lineOf(*objectsNode),
                         "scene has no objects: add at least one [[object]] table");
    }
    if (!objects || !objects->is_array_of_tables()) {
        std::string got = objects ? "an array of other values" : typeName(*objectsNode);
        throw InputError(sourceName, TableReader::lineOf(*objectsNode),
                         "object must be an array of tables ([[object]]), got " + got);
    }
    if (objects->size() > MAX_SCENE_OBJECTS) {
        throw InputError(sourceName, TableReader::lineOf(*objects->get(MAX_SCENE_OBJECTS)),
                         "scene has " + std::to_string(objects->size()) +
                             " objects; the limit is " + std::to_string(MAX_SCENE_OBJECTS));
    }
    std::map<std::string, int> firstLine;
    for (size_t i = 0; i < objects->size(); ++i) {
        const toml::table& objectTable = *objects->get(i)->as_table();
        SceneObject object = readObject(sourceName, objectTable, i);
        int line = TableReader::lineOf(objectTable);
        auto [it, inserted] = firstLine.emplace(object.name, line);
        if (!inserted) {
            const toml::node* nameNode = objectTable.get("name");
            throw InputError(sourceName, TableReader::lineOf(nameNode ? *nameNode : objectTable),
                             "object name '" + object.name + "' is used twice (first at line " +
                                 std::to_string(it->second) + ")");
        }
        scene.objects.push_back(std::move(object));
    }
    fitCameraPlanes(scene.camera, sceneBounds(scene));
    return scene;
}

Camera parseCameraToml(const toml::table& cameraTable, const std::string& sourceName,
                       const Scene& scene) {
    Camera camera = readCamera(sourceName, cameraTable);
    fitCameraPlanes(camera, sceneBounds(scene));
    return camera;
}

std::string formatSceneToml(const Scene& scene) {
    std::ostringstream s;
    const Camera& c = scene.camera;
    s << "[camera]\n";
    s << "eye = " << tomlVec(c.eyeWs) << "\n";
    s << "target = " << tomlVec(c.targetWs) << "\n";
    s << "up = " << tomlVec(c.upWs) << "\n";
    s << "fov = " << tomlFloat(c.fovYDeg) << "\n";
    if (c.nearZ > 0.0f) s << "near = " << tomlFloat(c.nearZ) << "\n";
    if (c.farZ > 0.0f) s << "far = " << tomlFloat(c.farZ) << "\n";
    const Light& l = scene.light;
    s << "\n[light]\n";
    s << "type = " << (l.type == LightType::Spot ? "\"spot\"" : "\"directional\"") << "\n";
    s << "direction = " << tomlVec(l.directionWs) << "\n";
    if (l.type == LightType::Spot) {
        s << "position = " << tomlVec(l.positionWs) << "\n";
        s << "cone = " << tomlFloat(l.coneDeg) << "\n";
        if (l.radius > 0.0f) s << "radius = " << tomlFloat(l.radius) << "\n";
    } else if (l.angularDiameterDeg > 0.0f) {
        s << "angular_diameter = " << tomlFloat(l.angularDiameterDeg) << "\n";
    }
    for (const SceneObject& object : scene.objects) {
        s << "\n[[object]]\n";
        s << "type = \"" << primitiveTypeName(object.shape) << "\"\n";
        s << "name = " << tomlString(object.name) << "\n";
        s << "colour = " << tomlVec(object.colour) << "\n";
        s << "casts_shadow = " << (object.castsShadow ? "true" : "false") << "\n";
        s << "receives_shadow = " << (object.receivesShadow ? "true" : "false") << "\n";
        if (const Plane* p = std::get_if<Plane>(&object.shape)) {
            s << "centre = " << tomlVec(p->centreWs) << "\n";
            s << "normal = " << tomlVec(p->normalWs) << "\n";
            s << "size = [" << tomlFloat(2.0f * glm::length(p->halfUWs)) << ", "
              << tomlFloat(2.0f * glm::length(p->halfVWs)) << "]\n";
            s << "tangent = " << tomlVec(glm::normalize(p->halfUWs)) << "\n";
        } else if (const Box* b = std::get_if<Box>(&object.shape)) {
            s << "centre = " << tomlVec(b->centreWs) << "\n";
            s << "half = " << tomlVec(b->halfExtents) << "\n";
            s << "rotate_y = " << tomlFloat(b->rotateYDeg) << "\n";
        } else if (const Sphere* sp = std::get_if<Sphere>(&object.shape)) {
            s << "centre = " << tomlVec(sp->centreWs) << "\n";
            s << "radius = " << tomlFloat(sp->radius) << "\n";
        }
    }
    return s.str();
}

}  // namespace pcf
