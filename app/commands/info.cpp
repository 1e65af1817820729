// pathspace info SCENE: what a scene contains and which capabilities it needs.
#include <iostream>
#include "command.h"
#include "report/converge.h"
#include "scene_loader.h"

namespace ps {
namespace {

int runInfo(const std::vector<std::string>& args) {
    if (args.size() != 1) throw UsageError("'info' takes one scene file");
    const Scene scene = loadScene(args[0]);
    std::cout << args[0] << ": " << scene.camera.width() << "x" << scene.camera.height() << " pixels, "
              << scene.triangles.size() << " triangles, " << scene.spheres.size() << " spheres, "
              << scene.materials.size() << " materials, " << scene.lights.size() << " lights, BVH depth "
              << scene.bvh.depth() << "\n  " << scene.caps.describe() << "\n  defaults: spp " << scene.settings.spp
              << ", maxdepth " << scene.settings.maxDepth << ", algo " << scene.settings.algo << "\n";
    for (const PointLightPixel& p : pointLightsInView(scene))
        std::cout << "  point light " << p.light << " is seen directly in pixel (" << p.x << ", " << p.y
                  << "): only light tracing and BPT draw it; converge leaves it out of the errors\n";
    return 0;
}

Command infoCommand() {
    Command c;
    c.name = "info";
    c.order = 30;
    c.synopsis = "info SCENE";
    c.summary = "print what the scene contains and needs";
    c.run = runInfo;
    return c;
}

}  // namespace

PS_REGISTER_COMMAND(infoCommand());

}  // namespace ps
