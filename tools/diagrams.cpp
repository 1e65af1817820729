// diagrams: the figures a lecturer draws on the board, one or more per lesson, written as SVG by code
// (labelled, viewBox-based, text at least 18 units high, about 15 px in a slide). scripts/figures.sh runs it; the lesson READMEs
// and slides show the SVGs it writes into lessons/NN-name/.
//
//   diagrams [LESSONS_DIR]     writes LESSONS_DIR/NN-name/*.svg (default: lessons; folders are created)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct P {
    double x, y;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator*(double s, P a) { return {s * a.x, s * a.y}; }
double length(P a) { return std::hypot(a.x, a.y); }
P normalize(P a) { return (1.0 / length(a)) * a; }
P lerp(P a, P b, double t) { return a + t * (b - a); }
P dir(double degrees) { return {std::cos(degrees * kPi / 180), -std::sin(degrees * kPi / 180)}; }  // y grows down
double angleOf(P d) { return std::atan2(-d.y, d.x) * 180 / kPi; }

// Colours: ink, light (emission and light subpaths), camera (importance and camera subpaths), a BSDF.
const char* kInk = "#222222";
const char* kLight = "#d98a00";
const char* kCamera = "#1f5fbf";
const char* kBsdf = "#2a9d5c";
const char* kGrey = "#888888";
const char* kRed = "#c0392b";

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", v);
    std::string s = b;
    if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
    return s;
}

// Text with light markup: _x or _{...} is a subscript, ^x or ^{...} a superscript.
std::string markup(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if ((c == '_' || c == '^') && i + 1 < s.size()) {
            std::string body;
            if (s[i + 1] == '{') {
                size_t end = s.find('}', i + 2);
                body = s.substr(i + 2, end - i - 2);
                i = end;
            } else {
                size_t n = 1;  // one UTF-8 character
                while (i + 1 + n < s.size() && (static_cast<unsigned char>(s[i + 1 + n]) & 0xC0) == 0x80) ++n;
                body = s.substr(i + 1, n);
                i += n;
            }
            const char* dy = c == '_' ? "0.3em" : "-0.45em";
            const char* back = c == '_' ? "-0.3em" : "0.45em";
            out += std::string("<tspan dy=\"") + dy + "\" font-size=\"72%\">" + markup(body) + "</tspan><tspan dy=\"" +
                   back + "\">\u200b</tspan>";
        } else if (c == '&') {
            out += "&amp;";
        } else if (c == '<') {
            out += "&lt;";
        } else if (c == '>') {
            out += "&gt;";
        } else {
            out += c;
        }
    }
    return out;
}

class Svg {
public:
    Svg(double w, double h) : w_(w), h_(h) {}
    void line(P a, P b, const char* colour, double width = 2.5, const char* dash = nullptr) {
        s_ << "<line x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(b.x) << "\" y2=\"" << num(b.y)
           << "\" stroke=\"" << colour << "\" stroke-width=\"" << num(width) << "\" stroke-linecap=\"round\""
           << (dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") << "/>\n";
    }
    // A line from a to b with an arrowhead at b.
    void arrow(P a, P b, const char* colour, double width = 2.5, const char* dash = nullptr) {
        P d = normalize(b - a), n{-d.y, d.x};
        double head = 8 + 3 * width;
        line(a, b - (0.8 * head) * d, colour, width, dash);
        polygon({b, b - head * d + (0.45 * head) * n, b - head * d - (0.45 * head) * n}, colour, colour);
    }
    void polygon(const std::vector<P>& ps, const char* fill, const char* stroke = "none", double opacity = 1,
                 double width = 2) {
        s_ << "<polygon points=\"";
        for (const P& p : ps) s_ << num(p.x) << "," << num(p.y) << " ";
        s_ << "\" fill=\"" << fill << "\" fill-opacity=\"" << num(opacity) << "\" stroke=\"" << stroke
           << "\" stroke-width=\"" << num(width) << "\" stroke-linejoin=\"round\"/>\n";
    }
    void polyline(const std::vector<P>& ps, const char* colour, double width = 2.5, const char* dash = nullptr) {
        s_ << "<polyline points=\"";
        for (const P& p : ps) s_ << num(p.x) << "," << num(p.y) << " ";
        s_ << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << num(width) << "\""
           << (dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") << " stroke-linejoin=\"round\"/>\n";
    }
    void circle(P c, double r, const char* fill, const char* stroke = "none", double width = 2, double opacity = 1) {
        s_ << "<circle cx=\"" << num(c.x) << "\" cy=\"" << num(c.y) << "\" r=\"" << num(r) << "\" fill=\"" << fill
           << "\" fill-opacity=\"" << num(opacity) << "\" stroke=\"" << stroke << "\" stroke-width=\"" << num(width)
           << "\"/>\n";
    }
    // A circular arc around c from angle a0 to a1 (degrees, counter-clockwise on screen).
    void arc(P c, double r, double a0, double a1, const char* colour, double width = 2) {
        P p0 = c + r * dir(a0), p1 = c + r * dir(a1);
        s_ << "<path d=\"M" << num(p0.x) << "," << num(p0.y) << " A" << num(r) << "," << num(r) << " 0 "
           << (std::fabs(a1 - a0) > 180 ? 1 : 0) << " " << (a1 > a0 ? 0 : 1) << " " << num(p1.x) << "," << num(p1.y)
           << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << num(width) << "\"/>\n";
    }
    // A filled wedge (circular sector) with apex c, around the direction `degrees`, half-angle `half`.
    void wedge(P c, double r, double degrees, double half, const char* colour, double opacity) {
        P p0 = c + r * dir(degrees - half), p1 = c + r * dir(degrees + half);
        s_ << "<path d=\"M" << num(c.x) << "," << num(c.y) << " L" << num(p0.x) << "," << num(p0.y) << " A" << num(r)
           << "," << num(r) << " 0 0 0 " << num(p1.x) << "," << num(p1.y) << " Z\" fill=\"" << colour
           << "\" fill-opacity=\"" << num(opacity) << "\" stroke=\"" << colour << "\" stroke-width=\"1.5\"/>\n";
    }
    void text(P at, const std::string& t, const char* anchor = "middle", double size = 20, const char* colour = kInk,
              bool italic = false) {
        s_ << "<text x=\"" << num(at.x) << "\" y=\"" << num(at.y) << "\" font-size=\"" << num(size)
           << "\" text-anchor=\"" << anchor << "\" fill=\"" << colour << "\""
           << (italic ? " font-style=\"italic\"" : "") << ">" << markup(t) << "</text>\n";
    }
    void dot(P c, const char* colour = kInk, double r = 6) { circle(c, r, colour); }
    bool save(const std::string& path) const {
        std::ofstream f(path);
        f << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << num(w_) << " " << num(h_)
          << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
          << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
          << s_.str() << "</svg>\n";
        return static_cast<bool>(f);
    }

private:
    double w_, h_;
    std::ostringstream s_;
};

// A deterministic stream of numbers in [0,1) (the figures must not change between runs).
struct Lcg {
    unsigned long long s = 12345;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
};

// A small surface normal: an arrow of length 38 from p in direction n.
void normal(Svg& s, P p, P n, const std::string& label = "") {
    s.arrow(p, p + 38 * normalize(n), kGrey, 2);
    if (!label.empty()) s.text(p + 52 * normalize(n) + P{14, 6}, label, "start", 18, kGrey);
}

// Lesson 0: a ray hits a triangle; the hit point's barycentric coordinates are area ratios.
Svg rayTriangle() {
    Svg s(960, 530);
    P p0{420, 380}, p1{860, 390}, p2{660, 50};  // the names of lessons/00 README, section 3
    double b1 = 0.32, b2 = 0.36;
    P p = (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2;
    s.polygon({p, p2, p0}, "#f4c27a", "none", 0.6);  // opposite p1: b1
    s.polygon({p, p0, p1}, "#9cc3f0", "none", 0.6);  // opposite p2: b2
    s.polygon({p, p1, p2}, "#a7dcb9", "none", 0.6);  // opposite p0: b0
    s.polygon({p0, p1, p2}, "none", kInk, 1, 3);
    for (P q : {p0, p1, p2}) s.line(p, q, kGrey, 1.5, "6 5");
    s.text((1.0 / 3) * (p + p2 + p0) + P{-8, 8}, "b_1", "middle", 24, kInk, true);
    s.text((1.0 / 3) * (p + p0 + p1) + P{0, 8}, "b_2", "middle", 24, kInk, true);
    s.text((1.0 / 3) * (p + p1 + p2) + P{10, 8}, "b_0", "middle", 24, kInk, true);
    s.text(p0 + P{-14, 24}, "p_0", "end", 22);
    s.text(p1 + P{14, 24}, "p_1", "start", 22);
    s.text(p2 + P{0, -16}, "p_2", "middle", 22);
    P o{70, 120};
    s.dot(o, kCamera);
    s.text(o + P{0, -18}, "o", "middle", 22, kCamera, true);
    s.arrow(o, lerp(o, p, 0.2), kCamera, 3.5);
    s.text(lerp(o, p, 0.12) + P{10, -16}, "d", "middle", 22, kCamera, true);
    s.line(lerp(o, p, 0.2), p, kCamera, 2.5);
    s.text(lerp(o, p, 0.55) + P{10, -14}, "t", "middle", 22, kCamera, true);
    s.dot(p, kRed, 7);
    s.text(p + P{16, -8}, "p", "start", 22, kRed, true);
    s.text({30, 450}, "p = o + t d = b_0 p_0 + b_1 p_1 + b_2 p_2,   b_0 = 1 − b_1 − b_2", "start", 20);
    s.text({30, 480}, "hit ⇔ b_0 ≥ 0, b_1 ≥ 0, b_2 ≥ 0 and 0 < t < t_{max}", "start", 20);
    s.text({30, 515}, "b_i = area of the sub-triangle opposite p_i / area of the triangle", "start", 18, kGrey);
    return s;
}

// Shirley's concentric map of the square onto the unit disk.
P concentric(double a, double b) {
    a = 2 * a - 1, b = 2 * b - 1;
    if (a == 0 && b == 0) return {0, 0};
    double r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a, phi = kPi / 4 * (b / a);
    } else {
        r = b, phi = kPi / 2 - kPi / 4 * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Lesson 1: cosine-weighted hemisphere sampling by lifting uniform points on the disk (Malley).
Svg cosineWarp() {
    Svg s(1000, 470);
    P c{200, 230};
    double R = 150;
    s.circle(c, R, "#eef3fb", kInk, 2.5);
    Lcg rng;
    std::vector<P> disk;
    const int n = 10;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) disk.push_back(concentric((i + rng.next()) / n, (j + rng.next()) / n));
    for (P d : disk) s.dot(c + R * P{d.x, -d.y}, kCamera, 3.5);
    s.text({c.x, 420}, "uniform points on the unit disk", "middle", 20);
    s.text({c.x, 448}, "(stratified, concentric map)", "middle", 18, kGrey);
    s.arrow({390, 230}, {520, 230}, kInk, 3);
    s.text({455, 212}, "lift", "middle", 20);
    s.text({455, 262}, "z = √(1 − x² − y²)", "middle", 18);
    // Side view: the disk edge-on and the hemisphere above it.
    P o{760, 360};
    double H = 190;
    s.arc(o, H, 0, 180, kInk, 2.5);
    s.line(o - P{H + 20, 0}, o + P{H + 20, 0}, kInk, 3);
    for (P d : disk) {
        if (std::fabs(d.y) > 0.12) continue;  // one thin slice of the disk, seen from the side
        double z = std::sqrt(std::max(0.0, 1 - d.x * d.x - d.y * d.y));
        P base = o + P{H * d.x, 0}, top = o + P{H * d.x, -H * z};
        s.line(base, top, kGrey, 1.5, "5 4");
        s.dot(base, kCamera, 4);
        s.dot(top, kRed, 5);
    }
    P w = o + H * dir(58);
    s.arrow(o, w, kInk, 2.5);
    s.line(o, o + P{0, -H - 20}, kGrey, 1.5);
    s.text(o + P{0, -H - 28}, "n", "middle", 20, kGrey, true);
    s.arc(o, 55, 58, 90, kInk, 2);
    s.text(o + 72 * dir(74), "θ", "middle", 22, kInk, true);
    s.text(w + P{14, -4}, "ω", "start", 22, kInk, true);
    s.text({o.x, 420}, "side view: directions crowd", "middle", 20);
    s.text({o.x, 448}, "around n: p(ω) = cos θ / π", "middle", 20);
    return s;
}

// Lesson 2: why Veach's plates need both techniques: the regions each one samples well.
void platePanel(Svg& s, double x0, double lobeHalf, double lightR, const std::string& title,
                const std::string& verdict) {
    P x{x0 + 130, 370};
    s.line(x - 110 * dir(-8), x + 110 * dir(-8), kInk, 7);  // the plate
    P light{x0 + 300, 175};
    double dist = length(light - x), lightDeg = angleOf(light - x);
    double lightHalf = std::asin(lightR / dist) * 180 / kPi;
    P eye{x0 + 10, 150};
    // Mirror direction of the eye about the plate's normal (the plate is tilted by -8 degrees).
    double eyeDeg = angleOf(eye - x), nDeg = 82;
    double reflDeg = 2 * nDeg - eyeDeg;
    s.wedge(x, dist, lightDeg, lightHalf, kLight, 0.28);
    s.wedge(x, 300, reflDeg, lobeHalf, kBsdf, 0.28);
    s.circle(light, lightR, "#ffd27a", kLight, 2.5);
    s.arrow(eye, lerp(eye, x, 0.93), kCamera, 2.5);
    s.text(eye + P{0, -14}, "eye", "middle", 18, kCamera);
    s.dot(x, kInk, 5);
    s.text(x + P{-8, 36}, "x", "middle", 20, kInk, true);
    s.text({x0 + 200, 40}, title, "middle", 20);
    s.text({x0 + 200, 440}, verdict, "middle", 18);
}

Svg misPlates() {
    Svg s(1000, 520);
    platePanel(s, 40, 5, 90, "shiny plate, big light", "BSDF sampling wins");
    platePanel(s, 540, 34, 14, "rough plate, small light", "light sampling wins");
    s.line({500, 20}, {500, 450}, "#cccccc", 2);
    s.polygon({{40, 478}, {64, 478}, {64, 498}, {40, 498}}, kBsdf, kBsdf, 0.35);
    s.text({72, 495}, "where BSDF sampling puts its samples", "start", 18);
    s.polygon({{520, 478}, {544, 478}, {544, 498}, {520, 498}}, kLight, kLight, 0.35);
    s.text({552, 495}, "where light sampling puts them", "start", 18);
    return s;
}

// A box seen in section (floor, ceiling, walls) with an area light in the ceiling.
// The side facing the camera is open.
void box(Svg& s, double l, double t, double r, double b, double lightL, double lightR, bool openLeft) {
    if (openLeft) s.polyline({{l, t}, {r, t}, {r, b}, {l, b}}, kInk, 3);
    else s.polyline({{r, t}, {l, t}, {l, b}, {r, b}}, kInk, 3);
    s.line({lightL, t}, {lightR, t}, kLight, 9);
}

// Lesson 3: a path with next-event estimation: at every vertex a shadow ray to a point on the light.
Svg neePath() {
    Svg s(1000, 565);
    box(s, 150, 40, 950, 440, 400, 560, true);
    s.polygon({{520, 440}, {660, 440}, {660, 370}, {520, 370}}, "#dddddd", kInk, 1, 2);  // a block
    P eye{40, 250}, x1{300, 440}, x2{950, 160}, x3{680, 440};
    s.circle(eye, 10, kCamera);
    s.text(eye + P{0, -22}, "camera", "middle", 18, kCamera);
    s.arrow(eye, x1, kInk, 3);
    s.arrow(x1, x2, kInk, 3);
    s.arrow(x2, x3, kInk, 3);
    s.arrow(x3, lerp(x3, {760, 170}, 0.6), kInk, 3);
    P y1{540, 40}, y2{470, 40}, y3{420, 40};
    s.line(x1, y1, kLight, 2.5, "10 7");
    s.line(x2, y2, kLight, 2.5, "10 7");
    s.line(x3, y3, kGrey, 2, "10 7");
    for (P y : {y1, y2}) s.dot(y, kLight, 6);
    s.dot(y3, kGrey, 6);
    P hit = lerp(x3, y3, 70.0 / 400);  // where the shadow ray meets the block's top
    s.line(hit + P{-10, -10}, hit + P{10, 10}, kRed, 4);
    s.line(hit + P{-10, 10}, hit + P{10, -10}, kRed, 4);
    s.text(hit + P{-20, -22}, "blocked: adds 0", "end", 18, kRed);
    int i = 0;  // x_0 is the camera ray's hit, as in (3.6)
    for (P x : {x1, x2, x3}) {
        s.dot(x, kInk, 7);
        s.text(x + (x.x > 900 ? P{-18, 34} : P{-16, 32}), "x_" + std::to_string(i++), "middle", 22, kInk, true);
    }
    s.text({580, 30}, "light", "start", 18, kLight);
    s.line({40, 490}, {90, 490}, kInk, 3);
    s.text({100, 497}, "BSDF-sampled direction (the walk)", "start", 18);
    s.line({480, 490}, {530, 490}, kLight, 2.5, "10 7");
    s.text({540, 497}, "shadow ray to a sampled light point (NEE)", "start", 18);
    s.text({40, 528},
           "every vertex adds L_e f G V / p_{light}; a BSDF ray that hits the light counts at depth 0 (pt-nee)",
           "start", 18, kGrey);
    s.text({40, 552}, "or with an MIS weight (pt)", "start", 18, kGrey);
    return s;
}

// Lesson 4: the pinhole sensor: image plane at distance 1, a pixel, the angle theta, the cos^4 falloff.
Svg pinholeWe() {
    Svg s(1000, 520);
    P e{90, 260};
    double plane = 330, half = 180;  // distance 1 = 330 units, tan(theta_y / 2) = 180 / 330
    P top{e.x + plane, e.y - half}, bottom{e.x + plane, e.y + half};
    s.line(top, bottom, kInk, 3);
    s.text(top + P{0, -14}, "image plane (distance 1)", "middle", 18);
    s.line(e, e + P{plane + 40, 0}, kGrey, 1.5, "6 5");
    s.text(lerp(e, e + P{plane, 0}, 0.5) + P{0, 26}, "1", "middle", 22, kGrey);
    // One pixel and the ray through its centre.
    double py0 = e.y - 158, py1 = e.y - 122;
    s.line({e.x + plane, py0}, {e.x + plane, py1}, kRed, 9);
    P pc{e.x + plane, 0.5 * (py0 + py1)};
    s.text(pc + P{18, 6}, "pixel j, area dA", "start", 18, kRed);
    s.arrow(e, e + 1.25 * (pc - e), kCamera, 2.5);
    s.polygon({e, {e.x + plane, py0}, {e.x + plane, py1}}, kRed, "none", 0.15);
    double theta = angleOf(pc - e);
    s.arc(e, 80, 0, theta, kInk, 2);
    s.text(e + 100 * dir(theta / 2), "θ", "middle", 22, kInk, true);
    s.text(lerp(e, pc, 0.55) + P{-24, -14}, "r = 1/cos θ", "end", 18, kCamera);
    s.circle(e, 8, kInk);
    s.text(e + P{0, 36}, "pinhole e", "middle", 18);
    s.text({40, 475}, "dω = cos θ dA / r² = cos³θ dA, and the sensor tilts by one more cos θ:", "start", 18);
    s.text({40, 505}, "W_e(ω) = 1 / (A cos⁴θ) makes every pixel read the mean radiance on its area", "start", 18);
    // The cos^4 falloff across the image plane.
    P o{600, 400};
    double W = 360, Hh = 300, smax = 1.5;
    s.line(o, o + P{W, 0}, kInk, 2);
    s.line(o + P{W / 2, 0}, o + P{W / 2, -Hh - 10}, kInk, 2);
    std::vector<P> curve;
    for (int i = 0; i <= 120; ++i) {
        double sv = -smax + 2 * smax * i / 120.0, c4 = 1 / ((1 + sv * sv) * (1 + sv * sv));
        curve.push_back(o + P{W / 2 + sv / smax * W / 2, -Hh * c4});
    }
    s.polyline(curve, kCamera, 3);
    s.text(o + P{W / 2 + 8, -Hh + 4}, "1", "start", 18);
    s.text(o + P{W / 2 + 40, -Hh + 30}, "cos⁴θ", "start", 20, kCamera);
    s.text(o + P{W / 2, 28}, "position s on the image plane", "middle", 18);
    s.text(o + P{W - 6, -50}, "0.09 at tan θ = 1.5", "end", 18, kGrey);
    return s;
}

// Lesson 5: a light path whose every vertex is connected to the pinhole and splatted to a pixel.
Svg lightSplat() {
    Svg s(1000, 560);
    box(s, 60, 40, 700, 440, 260, 420, false);
    P y0{340, 40}, y1{180, 440}, y2{60, 200}, y3{520, 440};
    P eye{930, 250};
    double planeX = 830;
    s.line({planeX, 120}, {planeX, 380}, kInk, 3);
    s.text({planeX, 105}, "image plane", "middle", 18);
    s.circle(eye, 9, kCamera);
    s.text(eye + P{0, 34}, "pinhole", "middle", 18, kCamera);
    s.arrow(y0, y1, kLight, 3);
    s.arrow(y1, y2, kLight, 3);
    s.arrow(y2, y3, kLight, 3);
    int i = 0;
    for (P y : {y0, y1, y2, y3}) {
        s.line(y, eye, kCamera, 2, "9 6");
        double t = (planeX - y.x) / (eye.x - y.x);
        P q = lerp(y, eye, t);
        s.polygon({q + P{-7, -7}, q + P{7, -7}, q + P{7, 7}, q + P{-7, 7}}, kRed, kRed, 0.85);
        s.dot(y, kLight, 7);
        P off = i == 0 ? P{-30, 30} : i == 2 ? P{24, -8} : P{0, 34};
        s.text(y + off, "y_" + std::to_string(i), i == 2 ? "start" : "middle", 22, kInk, true);
        ++i;
    }
    s.text({380, 28}, "light", "start", 18, kLight);
    s.line({60, 505}, {110, 505}, kLight, 3);
    s.text({120, 512}, "light path (sampled from the light)", "start", 18);
    s.line({480, 505}, {530, 505}, kCamera, 2, "9 6");
    s.text({540, 512}, "connection to the pinhole + shadow ray", "start", 18);
    s.polygon({{60, 527}, {74, 527}, {74, 541}, {60, 541}}, kRed, kRed, 0.85);
    s.text({84, 540}, "splat: β · f · G · W_e adds to the pixel the connection crosses", "start", 18);
    return s;
}

// Lesson 6: a path x0..x3 and its geometry terms; below, the four (s,t) splits of a path of length k = 2.
Svg pathVertices() {
    Svg s(1000, 575);
    P x0{90, 60}, x1{330, 215}, x2{600, 80}, x3{900, 200};
    s.line(x0 - P{60, 0}, x0 + P{60, 0}, kLight, 9);
    s.text(x0 + P{0, -16}, "light", "middle", 18, kLight);
    s.line(x1 - P{80, -8}, x1 + P{80, -8}, kInk, 4);
    s.line(x2 - P{80, 12}, x2 + P{80, 12}, kInk, 4);
    normal(s, x0, {0, 1});
    normal(s, x1, {0.1, -1});
    normal(s, x2, {-0.15, 1});
    s.arrow(x0, x1, kInk, 3);
    s.arrow(x1, x2, kInk, 3);
    s.arrow(x2, x3, kInk, 3);
    s.circle(x3, 9, kCamera);
    const char* names[] = {"x_0", "x_1", "x_2", "x_3"};
    P offs[] = {{-40, 34}, {0, 40}, {0, -20}, {0, 36}};
    int i = 0;
    for (P x : {x0, x1, x2, x3}) {
        if (i < 3) s.dot(x, kInk, 7);
        s.text(x + offs[i], names[i], "middle", 22, kInk, true);
        ++i;
    }
    s.text(x3 + P{0, -22}, "pinhole", "middle", 18, kCamera);
    s.text(lerp(x0, x1, 0.5) + P{-20, 8}, "G(x_0↔x_1)", "end", 18);
    s.text(lerp(x1, x2, 0.5) + P{34, 24}, "G(x_1↔x_2)", "start", 18);
    s.text(lerp(x2, x3, 0.5) + P{-30, 44}, "G(x_2↔x_3)", "start", 18);
    s.text({30, 298}, "G(x↔y) = V(x↔y) |cos θ_x| |cos θ_y| / ‖x − y‖²", "start", 19);
    s.text({30, 342}, "f(x̄) = L_e(x_0→x_1) G(x_0↔x_1) f_s(x_1) G(x_1↔x_2) f_s(x_2) G(x_2↔x_3) W_e(x_2→x_3)", "start",
           19);
    // The splits of a path of length k = 2 (three vertices, s + t = 3).
    s.text({30, 392}, "k = 2: techniques (s, t), s + t = 3, s light vertices and t camera vertices", "start", 19);
    const char* caption[] = {"(0,3): hits the light", "(1,2): next event", "(2,1): light tracing",
                             "(3,0): hits the pinhole"};
    for (int st = 0; st < 4; ++st) {
        double bx = 30 + 245 * st;
        P a{bx + 20, 420}, b{bx + 100, 510}, c{bx + 190, 440};
        P v[] = {a, b, c};
        for (int e = 0; e < 2; ++e) {
            int sLight = st;  // vertices 0 .. s-1 come from the light
            bool joined = (e + 1 == sLight);
            bool lightEdge = e + 1 < sLight;
            const char* col = joined ? kGrey : lightEdge ? kLight : kCamera;
            s.line(v[e], v[e + 1], col, 3, joined ? "8 6" : nullptr);
        }
        for (int k = 0; k < 3; ++k) s.dot(v[k], k < st ? kLight : kCamera, 8);
        s.text({bx + 105, 555}, caption[st], "middle", 18, st == 3 ? kGrey : kInk);
    }
    return s;
}

// Lesson 7: the techniques of one path of length 3 and their MIS weights.
Svg bptTechniques() {
    Svg s(1000, 520);
    s.text({30, 40}, "one path of length k = 3 (4 vertices), sampled by every technique (s, t), s + t = 4", "start",
           20);
    const char* caption[] = {"(0,4) hits light", "(1,3) next event", "(2,2) connect", "(3,1) light tracing",
                             "(4,0) impossible"};
    for (int st = 0; st < 5; ++st) {
        double bx = 10 + 196 * st;
        P v[] = {{bx + 30, 90}, {bx + 60, 290}, {bx + 150, 150}, {bx + 170, 300}};  // light ... camera
        s.line(v[0] - P{26, 0}, v[0] + P{26, 0}, kLight, 8);
        for (int e = 0; e < 3; ++e) {
            bool joined = (e + 1 == st), lightEdge = e + 1 < st;
            const char* col = joined ? kGrey : lightEdge ? kLight : kCamera;
            s.line(v[e], v[e + 1], col, 3.5, joined ? "8 6" : nullptr);
        }
        for (int k = 0; k < 4; ++k) {
            if (k == 3) s.circle(v[k], 9, k < st ? kLight : kCamera);
            else s.dot(v[k], k < st ? kLight : kCamera, 8);
        }
        s.text({bx + 95, 350}, caption[st], "middle", 18, st == 4 ? kGrey : kInk);
        std::string w = st == 4 ? "w = 0 (pinhole)" : "w_{" + std::to_string(st) + "," + std::to_string(4 - st) + "}";
        s.text({bx + 95, 380}, w, "middle", 20, st == 4 ? kGrey : kInk, st != 4);
        if (st > 0) s.line({bx - 8, 70}, {bx - 8, 390}, "#dddddd", 2);
    }
    s.text({30, 430},
           "power heuristic:  w_{s,t} = p_{s,t}² / Σ_{i} p_{i,4−i}²,   so  w_{0,4} + w_{1,3} + w_{2,2} + w_{3,1} = 1",
           "start", 20);
    s.text({30, 465}, "p_{s,t}: the area density with which technique (s, t) builds this very path", "start", 18,
           kGrey);
    s.line({30, 500}, {75, 500}, kLight, 3.5);
    s.text({82, 506}, "light subpath", "start", 18);
    s.line({250, 500}, {295, 500}, kCamera, 3.5);
    s.text({302, 506}, "camera subpath", "start", 18);
    s.line({480, 500}, {525, 500}, kGrey, 3.5, "8 6");
    s.text({532, 506}, "connecting edge (shadow ray)", "start", 18);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    std::string dir = argc > 1 ? argv[1] : "lessons";
    if (argc > 2 || dir == "-h" || dir == "--help") {
        std::fprintf(stderr, "usage: diagrams [LESSONS_DIR]   (writes LESSONS_DIR/NN-name/*.svg)\n");
        return 2;
    }
    struct Figure {
        const char* path;
        Svg svg;
    };
    std::vector<Figure> figures;
    figures.push_back({"00-rays/ray-triangle.svg", rayTriangle()});
    figures.push_back({"01-monte-carlo/cosine-warp.svg", cosineWarp()});
    figures.push_back({"02-direct-mis/mis-plates.svg", misPlates()});
    figures.push_back({"03-path-tracing/nee-path.svg", neePath()});
    figures.push_back({"04-measurement/pinhole-we.svg", pinholeWe()});
    figures.push_back({"05-light-tracing/light-splat.svg", lightSplat()});
    figures.push_back({"06-path-space/path-vertices.svg", pathVertices()});
    figures.push_back({"07-bidirectional/techniques-k3.svg", bptTechniques()});
    for (const Figure& f : figures) {
        std::string path = dir + "/" + f.path;
        std::error_code ec;
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
        if (ec || !f.svg.save(path)) {
            std::fprintf(stderr, "diagrams: cannot write %s\n", path.c_str());
            return 1;
        }
        std::printf("diagrams: wrote %s\n", path.c_str());
    }
    return 0;
}
