// diagrams: the figures a lecturer draws on the board, one or more per lesson, written as SVG by code
// (labelled, viewBox-based, text at least 18 units high, about 15 px in a slide). scripts/figures.sh runs it; the lesson READMEs
// and slides show the SVGs it writes into lessons/NN-name/.
//
//   diagrams [LESSONS_DIR]     writes LESSONS_DIR/NN-name/*.svg (default: lessons; folders are created)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

// Text with light markup: _x or _{...} is a subscript, ^x or ^{...} a superscript, ~{X} is X
// with a tilde above (for a Greek capital, which has no precomposed form).
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
        } else if (c == '~' && i + 1 < s.size() && s[i + 1] == '{') {  // ~{X}: X with a tilde above
            size_t end = s.find('}', i + 2);
            out += markup(s.substr(i + 2, end - i - 2)) +
                   "<tspan dx=\"-0.89em\" dy=\"-0.88em\" font-size=\"85%\">~</tspan><tspan dx=\"0.05em\" "
                   "dy=\"0.75em\">\u200b</tspan>";
            i = end;
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
    // A quadratic Bezier curve from a to b bent towards ctrl, with an arrowhead at b.
    void curveArrow(P a, P ctrl, P b, const char* colour, double width = 2) {
        P d = normalize(b - ctrl), n{-d.y, d.x};
        double head = 8 + 3 * width;
        P end = b - (0.8 * head) * d;
        s_ << "<path d=\"M" << num(a.x) << "," << num(a.y) << " Q" << num(ctrl.x) << "," << num(ctrl.y) << " "
           << num(end.x) << "," << num(end.y) << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\""
           << num(width) << "\"/>\n";
        polygon({b, b - head * d + (0.45 * head) * n, b - head * d - (0.45 * head) * n}, colour, colour);
    }
    void rect(P a, P b, const char* fill, const char* stroke = "none", double opacity = 1, double width = 2) {
        polygon({a, {b.x, a.y}, b, {a.x, b.y}}, fill, stroke, opacity, width);
    }

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
        for (int j = 0; j < n; ++j) {
            const double ux = rng.next(), uy = rng.next();  // in this order (a call's arguments have none)
            disk.push_back(concentric((i + ux) / n, (j + uy) / n));
        }
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

// Lesson 1: 64 points three ways: independent random, jittered (one per cell of 8 x 8), and the
// first 64 Halton points (bases 2 and 3, Eq. 1.19).
double digitsMirrored(int i, int base) {  // Eq. 1.15 for the small indices drawn here
    double value = 0, weight = 1.0 / base;
    for (; i > 0; i /= base, weight /= base) value += (i % base) * weight;
    return value;
}

Svg lowDiscrepancy() {
    Svg s(1000, 420);
    const double side = 280, top = 40;
    const char* titles[] = {"random", "stratified (8 × 8, jittered)", "Halton (bases 2, 3)"};
    Lcg rng;
    for (int panel = 0; panel < 3; ++panel) {
        const P corner{30 + panel * 330.0, top};
        s.rect(corner, corner + P{side, side}, "#f7f9fc", kInk, 1, 2);
        for (int k = 1; k < 8 && panel == 1; ++k) {
            s.line(corner + P{side * k / 8, 0}, corner + P{side * k / 8, side}, "#dddddd", 1);
            s.line(corner + P{0, side * k / 8}, corner + P{side, side * k / 8}, "#dddddd", 1);
        }
        for (int i = 0; i < 64; ++i) {
            double x, y;
            if (panel == 0) {
                x = rng.next();
                y = rng.next();
            } else if (panel == 1) {
                x = (i % 8 + rng.next()) / 8;
                y = (i / 8 + rng.next()) / 8;
            } else {
                x = digitsMirrored(i, 2);
                y = digitsMirrored(i, 3);
            }
            s.dot(corner + P{side * x, side * (1 - y)}, panel == 2 ? kCamera : kInk, 4.5);
        }
        s.text(corner + P{side / 2, side + 36}, titles[panel], "middle", 20);
    }
    s.text({500, 400}, "the same 64 samples: random points clump and leave holes; Halton fills every gap, with no grid",
           "middle", 18, kGrey);
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


// Lesson 8: a left-balanced kd-tree of 12 photons stored in one array in heap order, and one
// k-nearest query that never enters half of the tree (8.4, 8.5). The tree is given, not built
// here (building it is the lesson's task); main checks that it is a kd-tree in heap order.
struct KdNode {
    P p;       // position in the unit square (y up)
    int axis;  // split axis of an inner node: 0 = x, 1 = y; -1 for a leaf
};
// Node i at index i (index 0 unused); node i's children are 2i and 2i + 1.
const std::vector<KdNode> kKdTree = {{{0, 0}, -1},       {{0.66, 0.90}, 0},  {{0.33, 0.45}, 1},  {{0.80, 0.55}, 1},
                                     {{0.42, 0.12}, 0},  {{0.27, 0.85}, 0},  {{0.93, 0.30}, 0},  {{0.88, 0.80}, -1},
                                     {{0.18, 0.22}, -1}, {{0.58, 0.35}, -1}, {{0.08, 0.62}, -1}, {{0.50, 0.66}, -1},
                                     {{0.72, 0.18}, -1}};
const int kKdSize = static_cast<int>(kKdTree.size()) - 1;

double coord(P p, int axis) { return axis == 0 ? p.x : p.y; }
// The nodes of the subtree rooted at i.
std::vector<int> subtree(int i) {
    std::vector<int> out;
    if (i > kKdSize) return out;
    out.push_back(i);
    for (int c : {2 * i, 2 * i + 1})
        for (int j : subtree(c)) out.push_back(j);
    return out;
}
// Every photon of a node's left subtree lies at or below its split, of the right at or above;
// a node has children exactly when it has a split axis.
bool isHeapKdTree() {
    for (int i = 1; i <= kKdSize; ++i) {
        const KdNode& n = kKdTree[i];
        if ((n.axis >= 0) != (2 * i <= kKdSize)) return false;
        if (n.axis < 0) continue;
        for (int j : subtree(2 * i))
            if (coord(kKdTree[j].p, n.axis) > coord(n.p, n.axis)) return false;
        for (int j : subtree(2 * i + 1))
            if (coord(kKdTree[j].p, n.axis) < coord(n.p, n.axis)) return false;
    }
    return true;
}
// The squared distance of the k-th nearest of `nodes` to x (brute force).
double kthNearest2(std::vector<int> nodes, P x, int k) {
    std::vector<double> d2;
    for (int j : nodes) d2.push_back(std::pow(length(kKdTree[j].p - x), 2));
    std::sort(d2.begin(), d2.end());
    return d2[k - 1];
}

// The split lines of the subtree at i inside its cell [lo, hi] (unit square coordinates).
void splitLines(Svg& s, int i, P lo, P hi, P (*toScreen)(P), const char* colour) {
    if (i > kKdSize || kKdTree[i].axis < 0) return;
    const KdNode& n = kKdTree[i];
    P a = n.axis == 0 ? P{n.p.x, lo.y} : P{lo.x, n.p.y}, b = n.axis == 0 ? P{n.p.x, hi.y} : P{hi.x, n.p.y};
    s.line(toScreen(a), toScreen(b), colour, i == 1 ? 3 : 2);
    splitLines(s, 2 * i, lo, n.axis == 0 ? P{n.p.x, hi.y} : P{hi.x, n.p.y}, toScreen, colour);
    splitLines(s, 2 * i + 1, n.axis == 0 ? P{n.p.x, lo.y} : P{lo.x, n.p.y}, hi, toScreen, colour);
}

P kdScreen(P u) { return {50 + 400 * u.x, 470 - 400 * u.y}; }

Svg kdTreeQuery() {
    Svg s(1000, 600);
    const P x{0.25, 0.30};
    const int k = 3;
    // The search (8.5) at the root: node 2's side first; node 3's side only if delta^2 <= d2max.
    const double delta = x.x - kKdTree[1].p.x;
    const double boundAfterLeft = kthNearest2(subtree(2), x, k);
    if (delta * delta <= boundAfterLeft) {  // the figure says node 3's side is skipped
        std::fprintf(stderr, "diagrams: the kd-tree query searches both sides of the root; move x\n");
        std::exit(1);
    }
    std::vector<int> all = subtree(1);
    const double r = std::sqrt(kthNearest2(all, x, k));
    const std::vector<int> skipped = subtree(3);
    auto isSkipped = [&](int i) { return std::find(skipped.begin(), skipped.end(), i) != skipped.end(); };

    // Left: the photons in the plane, the split lines, the query.
    s.rect(kdScreen({kKdTree[1].p.x, 0}), kdScreen({1, 1}), "#e6e6e6", "none", 1);
    s.rect(kdScreen({0, 0}), kdScreen({1, 1}), "none", kInk, 1, 2.5);
    splitLines(s, 1, {0, 0}, {1, 1}, kdScreen, kGrey);
    s.text(kdScreen({0.79, 0.11}), "never", "middle", 18, kGrey);
    s.text(kdScreen({0.79, 0.11}) + P{0, 22}, "searched", "middle", 18, kGrey);
    s.circle(kdScreen(x), 400 * r, kRed, kRed, 2.5, 0.08);
    s.circle(kdScreen(x), 400 * r, "none", kRed, 2.5);
    for (int i = 1; i <= kKdSize; ++i) {
        P c = kdScreen(kKdTree[i].p);
        bool found = length(kKdTree[i].p - x) <= r + 1e-12;
        if (found) s.circle(c, 12, "none", kRed, 3);
        s.dot(c, isSkipped(i) ? kGrey : kLight, 7);
        s.text(c + P{11, -10}, std::to_string(i), "start", 18, isSkipped(i) ? kGrey : kInk);
    }
    P xs = kdScreen(x), split = kdScreen({kKdTree[1].p.x, x.y});
    s.line(xs + P{-9, -9}, xs + P{9, 9}, kRed, 3.5);
    s.line(xs + P{-9, 9}, xs + P{9, -9}, kRed, 3.5);
    s.text(xs + P{0, -16}, "x", "middle", 22, kRed, true);
    s.arrow(xs + P{14, 0}, split, kInk, 2);
    s.text(lerp(xs, split, 0.55) + P{0, -10}, "δ", "middle", 22, kInk, true);
    s.text(kdScreen({0, 0}) + P{0, 28}, "12 photons, the split lines of their nodes", "start", 18);

    // Right: the tree, level by level, and the array it lives in.
    auto nodeAt = [](int i) {
        int level = 0;
        while ((2 << level) <= i) ++level;
        double slot = 420.0 / (1 << level);
        return P{540 + slot * (i - (1 << level) + 0.5), 95 + 78.0 * level};
    };
    for (int i = 2; i <= kKdSize; ++i)
        s.line(nodeAt(i / 2), nodeAt(i), isSkipped(i) ? "#bbbbbb" : kInk, 2, isSkipped(i) ? "6 5" : nullptr);
    for (int i = 1; i <= kKdSize; ++i) {
        P c = nodeAt(i);
        s.circle(c, 17, isSkipped(i) ? "#eeeeee" : "#fbe3bd", isSkipped(i) ? "#bbbbbb" : kLight, 2);
        s.text(c + P{0, 6}, std::to_string(i), "middle", 18, isSkipped(i) ? kGrey : kInk);
        if (kKdTree[i].axis >= 0) s.text(c + P{22, -8}, kKdTree[i].axis == 0 ? "x" : "y", "start", 18, kGrey, true);
    }
    s.text({540, 50}, "the tree: each level full but the last, packed left", "start", 18);
    const double cell = 420.0 / kKdSize, ay = 420;
    for (int i = 1; i <= kKdSize; ++i) {
        P a{540 + cell * (i - 1), ay}, b{540 + cell * i, ay + 36};
        s.rect(a, b, isSkipped(i) ? "#eeeeee" : "#fbe3bd", kInk, 1, 1.5);
        s.text({0.5 * (a.x + b.x), ay + 25}, std::to_string(i), "middle", 18);
    }
    auto cellTop = [&](int i) { return P{540 + cell * (i - 0.5), ay - 2}; };
    for (int c : {4, 5})
        s.curveArrow(cellTop(2), 0.5 * (cellTop(2) + cellTop(c)) + P{0, c == 4 ? -30.0 : -56.0}, cellTop(c), kCamera);
    s.text({540, ay + 62}, "one array in heap order, no pointers:", "start", 18);
    s.text({540, ay + 86}, "node i's children are 2i and 2i + 1", "start", 18);

    const int nLeft = static_cast<int>(subtree(2).size());
    s.text({40, 548},
           "left-balanced: n = " + std::to_string(kKdSize) + " photons fill nodes 1 … " + std::to_string(kKdSize) +
               ", the root's left subtree holds n_{left} = " + std::to_string(nLeft) + " (8.4)",
           "start", 18);
    s.text({40, 578},
           "k = " + std::to_string(k) +
               " nearest of x (ringed): after node 2's side d²_{max} < δ², so node 3's side "
               "is skipped (8.5)",
           "start", 18);
    return s;
}


// Lesson 9: a Metropolis chain in primary sample space: small steps, large steps, and the
// acceptance a = min(1, I(y) / I(x)) (9.2, 9.8, 9.9). Two primary samples (u_0, u_1) stand for
// the whole vector; I is a made-up luminance with two bright regions.
struct Blob {
    P c;
    double sigma, height;
};
const Blob kBlobs[] = {{{0.68, 0.36}, 0.12, 1.0}, {{0.26, 0.72}, 0.10, 0.6}};
double luminance(P u) {
    double v = 0.03;
    for (const Blob& b : kBlobs) v += b.height * std::exp(-std::pow(length(u - b.c), 2) / (2 * b.sigma * b.sigma));
    return v;
}
P pssScreen(P u) { return {50 + 400 * u.x, 470 - 400 * u.y}; }

Svg metropolisChain() {
    Svg s(1000, 600);
    // I(u) as nested level sets of each bright region.
    for (const Blob& b : kBlobs)
        for (double level : {0.1, 0.3, 0.5, 0.7, 0.9})
            s.circle(pssScreen(b.c), 400 * b.sigma * std::sqrt(-2 * std::log(level)), kLight, "none", 2,
                     0.16 * b.height);
    s.rect(pssScreen({0, 0}), pssScreen({1, 1}), "none", kInk, 1, 2.5);
    s.text(pssScreen({0.5, 0}) + P{0, 30}, "u_0", "middle", 20, kInk, true);
    s.text(pssScreen({0, 0.5}) + P{-14, 6}, "u_1", "end", 20, kInk, true);
    s.text(pssScreen({0, 1}) + P{0, -14}, "[0, 1)², wrapped around: a torus", "start", 18);
    // The proposals: where each step goes and the uniform number that decides it.
    struct Step {
        bool large;
        P to;
        double xi;
        P label;  // where its number goes, from the proposal
    };
    const Step steps[] = {{false, {0.58, 0.25}, 0.52, {14, 20}},  {false, {0.66, 0.34}, 0.90, {-16, -10}},
                          {false, {0.79, 0.45}, 0.74, {12, -10}}, {true, {0.12, 0.14}, 0.40, {-4, 30}},
                          {true, {0.33, 0.65}, 0.31, {12, -10}},  {false, {0.24, 0.75}, 0.66, {12, -10}}};
    P x{0.48, 0.17};
    s.dot(pssScreen(x), kCamera, 8);
    s.text(pssScreen(x) + P{-12, 22}, "x_0", "end", 20, kCamera, true);
    const double tx = 520, ty = 78, col[] = {0, 50, 125, 245, 320, 390};
    const char* head[] = {"step", "kind", "I(y) / I(x)", "a", "ξ", ""};
    for (int c = 0; c < 6; ++c) s.text({tx + col[c], ty}, head[c], "start", 18, kInk, c == 3 || c == 4);
    s.line({tx, ty + 10}, {tx + 460, ty + 10}, kInk, 1.5);
    int i = 1;
    for (const Step& st : steps) {
        const double ratio = luminance(st.to) / luminance(x), a = std::min(1.0, ratio);
        const bool accepted = st.xi < a;
        const char* colour = st.large ? kBsdf : kCamera;
        P from = pssScreen(x), to = pssScreen(st.to);
        P end = to - 11 * normalize(to - from);
        if (accepted) {
            s.arrow(from, end, colour, 2.5);
            s.dot(to, kCamera, 8);
        } else {
            s.arrow(from, end, colour, 2, "7 5");
            s.circle(to, 8, "white", kRed, 2.5);
        }
        s.text(to + st.label, std::to_string(i), "start", 18, accepted ? kInk : kRed);
        char r[16], av[16], xv[16];
        std::snprintf(r, sizeof r, "%.2f", ratio);
        std::snprintf(av, sizeof av, "%.2f", a);
        std::snprintf(xv, sizeof xv, "%.2f", st.xi);
        const double y = ty + 38 + 30.0 * (i - 1);
        const std::string cells[] = {
            std::to_string(i), st.large ? "large" : "small", r, av, xv, accepted ? "accept" : "reject"};
        for (int c = 0; c < 6; ++c)
            s.text({tx + col[c], y}, cells[c], "start", 18, c == 1 ? colour : c == 5 ? (accepted ? kInk : kRed) : kInk);
        if (accepted) x = st.to;
        ++i;
    }
    const double ly = ty + 38 + 30.0 * i;
    s.text({tx, ly}, "a = min(1, I(y) / I(x)): both steps are", "start", 18);
    s.text({tx, ly + 26}, "symmetric, T cancels (9.2); accept if ξ < a,", "start", 18);
    s.text({tx, ly + 52}, "else the chain stays where it is", "start", 18);
    s.text({tx, ly + 88}, "small: u_k' = u_k ± s_2 e^{−ln(s_2/s_1) ξ} mod 1 (9.9)", "start", 18, kCamera);
    s.text({tx, ly + 114}, "large: u_k' = ξ_k (9.8), probability p_{large}", "start", 18, kBsdf);
    // Legend.
    s.arrow({50, 525}, {100, 525}, kCamera, 2.5);
    s.text({110, 531}, "small step (drawn enlarged)", "start", 18);
    s.arrow({380, 525}, {430, 525}, kBsdf, 2.5);
    s.text({440, 531}, "large step", "start", 18);
    s.circle({600, 525}, 8, "white", kRed, 2.5);
    s.text({616, 531}, "rejected proposal", "start", 18);
    s.circle({800, 525}, 8, "#fbe3bd", "none");
    s.circle({800, 525}, 5, kLight, "none", 2, 0.5);
    s.text({816, 531}, "bright I(u)", "start", 18);
    s.text({50, 572}, "both proposals splat: f/I at x with weight 1 − a, at y with weight a (9.11)", "start", 18,
           kGrey);
    return s;
}


// Lesson 10: the weight window around the centre C_ww = I~ / Psi~ (10.5-10.7): roulette below it,
// nothing inside, splitting above, q clamped at both ends; one path of each kind.
Svg weightWindow() {
    Svg s(1000, 570);
    const double sRatio = 5, qMin = 0.05, qMax = 8;                       // s, q_min, q_max of (10.6), (10.7)
    const double lower = 2 / (1 + sRatio), upper = sRatio * lower;        // delta^-, delta^+ with C_ww = 1
    auto at = [](double nu) { return 60 + 220 * (std::log10(nu) + 2); };  // nu / C_ww from 0.01 to 100
    const double top = 90, bottom = 330, xl = at(lower), xu = at(upper), xc = at(1);
    const double xMin = at(qMin * lower), xMax = at(qMax * upper);
    s.rect({at(0.01), top}, {xl, bottom}, "#f6d5d0", "none");
    s.rect({at(0.01), top}, {xMin, bottom}, "#eab2aa", "none");
    s.rect({xl, top}, {xu, bottom}, "#cfeedd", "none");
    s.rect({xu, top}, {at(100), bottom}, "#d6e3f6", "none");
    s.rect({xMax, top}, {at(100), bottom}, "#b4cbef", "none");
    s.text({0.5 * (xMin + xl), top + 28}, "Russian roulette", "middle", 20, kRed);
    s.text({0.5 * (xMin + xl), top + 54}, "q = ν / δ^− < 1", "middle", 18);
    s.text({0.5 * (xl + xu), top + 28}, "window", "middle", 20, kBsdf);
    s.text({0.5 * (xl + xu), top + 54}, "q = 1", "middle", 18);
    s.text({0.5 * (xu + xMax), top + 28}, "splitting", "middle", 20, kCamera);
    s.text({0.5 * (xu + xMax), top + 54}, "q = ν / δ^+ > 1", "middle", 18);
    s.text({0.5 * (at(0.01) + xMin), top + 28}, "q_{min}", "middle", 18);
    s.text({0.5 * (xMax + at(100)), top + 28}, "q = q_{max}", "middle", 18);
    for (double x : {xl, xu}) s.line({x, top}, {x, bottom + 10}, kInk, 2);
    s.line({xc, top + 70}, {xc, bottom + 10}, kInk, 1.5, "6 5");
    s.text({xl, bottom + 34}, "δ^−", "middle", 22, kInk, true);
    s.text({xu, bottom + 34}, "δ^+", "middle", 22, kInk, true);
    s.text({xc, bottom + 34}, "C_{ww}", "middle", 22, kInk, true);
    // The axis: the path's weight nu in units of C_ww, on a log scale.
    const double ay = bottom + 60;
    s.arrow({at(0.01), ay}, {at(100) + 24, ay}, kInk, 2);
    const char* decade[] = {"0.01", "0.1", "1", "10", "100"};
    for (int d = 0; d < 5; ++d) {
        const double x = at(std::pow(10.0, d - 2));
        s.line({x, ay - 7}, {x, ay + 7}, kInk, 2);
        s.text({x, ay + 28}, decade[d], "middle", 18);
    }
    s.text({at(100) + 24, ay + 54}, "ν / C_{ww}, log scale", "end", 18, kInk, true);
    // One path below the window: roulette with q = 1/8, the survivor weighs delta^-.
    const double nuLow = lower / 8, yLow = 215;
    s.dot({at(nuLow), yLow}, kInk, 8);
    s.text({at(nuLow), yLow + 30}, "ν", "middle", 20, kInk, true);
    s.arrow({at(nuLow) + 10, yLow}, {xl - 4, yLow}, kInk, 2.5);
    s.text({at(nuLow) + 60, yLow - 14}, "q = 1/8", "start", 18);
    s.line({at(nuLow) - 8, yLow + 48}, {at(nuLow) + 8, yLow + 64}, kRed, 3.5);
    s.line({at(nuLow) - 8, yLow + 64}, {at(nuLow) + 8, yLow + 48}, kRed, 3.5);
    s.text({at(nuLow) + 16, yLow + 62}, "ends with 1 − q", "start", 18, kRed);
    // One inside: unchanged.
    s.dot({at(0.8), yLow}, kInk, 8);
    s.text({at(0.8), yLow + 30}, "ν", "middle", 20, kInk, true);
    // One above: split, E[n] = q = 3.5, each part weighs delta^+.
    const double nuHigh = 3.5 * upper;
    const P high{at(nuHigh), yLow};
    s.dot(high, kInk, 8);
    s.text(high + P{0, 30}, "ν", "middle", 20, kInk, true);
    for (int k = 0; k < 4; ++k) {
        P end{xu + 6, yLow - 45 + 30 * k};
        s.arrow(high + 10 * normalize(end - high), end, kCamera, 2.5, k == 3 ? "6 5" : nullptr);
    }
    s.text({xu + 12, yLow + 76}, "q = 3.5: n = 3 or 4,", "start", 18);
    s.text({xu + 12, yLow + 100}, "E[n] = q", "start", 18);
    s.text({40, 40}, "a path of weight ν (10.5) meets the window: each continuation goes on with weight ν / q", "start",
           18);
    s.text({40, 66}, "(the survivor of the roulette with δ^−, each part of a split with δ^+)", "start", 18, kGrey);
    s.text({40, 490}, "C_{ww} = Ĩ / ~{Ψ} (10.5),   δ^− = 2 C_{ww} / (1 + s),   δ^+ = s δ^−,   s = 5 (10.6)", "start",
           18);
    s.text({40, 520}, "q clamped to [q_{min}, q_{max}] = [0.05, 8] (10.7); n = ⌊q⌋ or ⌊q⌋ + 1 with E[n] = q (10.4)",
           "start", 18);
    s.text({40, 550}, "unbiased for any q > 0: E[n] · β/q = β (10.3)", "start", 18, kGrey);
    return s;
}

// Lesson 12: the learned field. Left, a room seen from above, cut by the spatial tree (a binary
// tree that halves a box across x, then y, ...) where the path vertices were many; right, one
// cell's directional distribution: a quadtree over the square of the cylindrical map, cut where
// the energy is (Eq. 12.5-12.11), shaded by density.
struct GuideBox {
    double x0, y0, x1, y1;
};
// The expected number of path vertices in a box: a density over the room, higher near the lit
// patch under the lamp (a product of two bumps, integrated by a midpoint rule).
double vertexMass(const GuideBox& b) {
    double m = 0.0;
    const int n = 8;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = b.x0 + (i + 0.5) * (b.x1 - b.x0) / n, y = b.y0 + (j + 0.5) * (b.y1 - b.y0) / n;
            m += 0.3 + 6.0 * std::exp(-((x - 0.68) * (x - 0.68) + (y - 0.3) * (y - 0.3)) / 0.02);
        }
    return m * (b.x1 - b.x0) * (b.y1 - b.y0) / (n * n);
}
void spatialCells(const GuideBox& b, int axis, double threshold, std::vector<GuideBox>& out) {
    if (vertexMass(b) <= threshold) {
        out.push_back(b);
        return;
    }
    GuideBox lo = b, hi = b;
    if (axis == 0) lo.x1 = hi.x0 = 0.5 * (b.x0 + b.x1);
    else lo.y1 = hi.y0 = 0.5 * (b.y0 + b.y1);
    spatialCells(lo, 1 - axis, threshold, out);
    spatialCells(hi, 1 - axis, threshold, out);
}
// The incident radiance over the square (u = (1 - cos theta) / 2, v = phi / 2 pi) at the chosen
// cell: a bright small lamp, a dimmer lit wall, a little everywhere.
double radianceAt(double u, double v) {
    const auto bump = [](double du, double dv, double w) { return std::exp(-(du * du + dv * dv) / w); };
    return 0.004 + 8.0 * bump(u - 0.22, v - 0.63, 0.002) + 1.2 * bump(u - 0.55, v - 0.2, 0.02);
}
double squareEnergy(double x, double y, double size) {
    double e = 0.0;
    const int n = 6;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) e += radianceAt(x + (i + 0.5) * size / n, y + (j + 0.5) * size / n);
    return e * size * size / (n * n);
}
struct QuadLeaf {
    double x, y, size, energy;
};
void quadLeaves(double x, double y, double size, double total, double rho, int depth, std::vector<QuadLeaf>& out) {
    const double e = squareEnergy(x, y, size);
    if (e <= rho * total || depth >= 7) {
        out.push_back({x, y, size, e});
        return;
    }
    const double h = 0.5 * size;
    for (int i = 0; i < 4; ++i) quadLeaves(x + (i & 1) * h, y + (i >> 1) * h, h, total, rho, depth + 1, out);
}
Svg guidingField() {
    Svg s(1000, 660);
    s.text({40, 38}, "the learned field: a spatial tree over the scene, a directional quadtree in each cell", "start",
           20);
    // Left: the room from above, 400 x 400.
    const P o{40, 110};
    const double side = 380;
    auto at = [&](double x, double y) { return P{o.x + side * x, o.y + side * y}; };
    std::vector<GuideBox> cells;
    spatialCells({0, 0, 1, 1}, 0, 0.02, cells);
    const GuideBox* chosen = nullptr;
    for (const GuideBox& c : cells) {
        s.rect(at(c.x0, c.y0), at(c.x1, c.y1), "#f7f7f7", kGrey, 1, 1.2);
        if (c.x0 <= 0.52 && c.x1 > 0.52 && c.y0 <= 0.42 && c.y1 > 0.42) chosen = &c;
    }
    s.rect(at(0, 0), at(1, 1), "none", kInk, 1, 3);
    // The lamp's lit patch on the floor, and a few path vertices (more where the light is).
    s.circle(at(0.68, 0.3), 0.07 * side, kLight, "none", 2, 0.25);
    s.text(at(0.68, 0.3) + P{0.1 * side, 0.14 * side}, "lit patch", "start", 18, kLight);
    Lcg rng;
    for (int k = 0; k < 140; ++k) {
        double x = rng.next(), y = rng.next();
        if (k % 2) {
            x = 0.68 + 0.16 * (rng.next() - 0.5);
            y = 0.3 + 0.16 * (rng.next() - 0.5);
        }
        s.dot(at(x, y), kCamera, 2.2);
    }
    if (chosen) s.rect(at(chosen->x0, chosen->y0), at(chosen->x1, chosen->y1), kBsdf, kBsdf, 0.25, 3);
    s.text({o.x, o.y + side + 34}, "a leaf is halved (x, then y, ...) when a pass", "start", 18);
    s.text({o.x, o.y + side + 58}, "recorded more than c √(2^k) vertices in it (12.11)", "start", 18);
    s.text({o.x, o.y - 40}, "the scene from above, cut by the spatial tree;", "start", 18, kGrey);
    s.text({o.x, o.y - 16}, "dots: the path vertices of one pass", "start", 18, kGrey);
    // Right: the chosen cell's quadtree over the square, 360 x 360.
    const P q{580, 110};
    const double qs = 360;
    const double total = squareEnergy(0, 0, 1);
    std::vector<QuadLeaf> leaves;
    quadLeaves(0, 0, 1, total, 0.01, 0, leaves);
    double maxDensity = 0.0;
    for (const QuadLeaf& l : leaves) maxDensity = std::max(maxDensity, l.energy / (l.size * l.size));
    for (const QuadLeaf& l : leaves) {
        const double d = std::pow(l.energy / (l.size * l.size) / maxDensity, 0.45);
        char fill[16];
        const int r = int(255 - d * (255 - 0xd9)), g = int(255 - d * (255 - 0x8a)), b = int(255 - d * 255);
        std::snprintf(fill, sizeof fill, "#%02x%02x%02x", r, g, b);
        s.rect({q.x + qs * l.x, q.y + qs * l.y}, {q.x + qs * (l.x + l.size), q.y + qs * (l.y + l.size)}, fill, kGrey, 1,
               0.8);
    }
    s.rect(q, {q.x + qs, q.y + qs}, "none", kInk, 1, 3);
    if (chosen) {
        const P from = at(chosen->x1, 0.5 * (chosen->y0 + chosen->y1));
        s.curveArrow(from, {0.5 * (from.x + q.x), q.y + qs + 40}, {q.x - 8, q.y + 0.6 * qs}, kBsdf, 2.5);
    }
    s.text({q.x, q.y - 40}, "one cell's directional distribution:", "start", 18, kGrey);
    s.text({q.x, q.y - 16}, "a quadtree over the cylindrical square", "start", 18, kGrey);
    s.text({q.x + qs, q.y + qs + 30}, "s_x = (1 − cos θ) / 2 →", "end", 18, kInk, true);
    s.text({q.x - 10, q.y + 20}, "s_y = φ / 2π", "end", 18, kInk, true);
    s.text({q.x - 10, q.y + 46}, "↓", "end", 18, kInk, true);
    s.text({q.x + 0.22 * qs + 24, q.y + 0.63 * qs - 14}, "the lamp", "start", 18, kLight);
    s.text({q.x + 0.55 * qs, q.y + 0.2 * qs + 48}, "lit wall", "middle", 18, kLight);
    s.text({q.x, q.y + qs + 58}, "a quadrant is cut while it holds more than", "start", 18);
    s.text({q.x, q.y + qs + 82}, "ρ = 1 % of the cell's energy (12.9)", "start", 18);
    s.text({40, 600}, "p(ω) = p_{square}(s) / 4π (12.5); p_{square} is the product, over the levels down to the leaf,",
           "start", 18);
    s.text({40, 626}, "of 4 × the quadrant's share of its node's energy (12.6)", "start", 18);
    return s;
}

// Lesson 11: the family tree of the classics in Heckbert's notation (11.1): each box carries a
// subset of the paths of the box it hangs from; the edges say what was taken away.
struct FamilyNode {
    P centre;
    double width;
    const char* name;
    const char* paths;
    const char* note;
};
// The family tree is shown on a lecture slide 470 pixels high: its text is 27 to 33 units in a
// 1000 x 662 drawing, 19 to 23 pixels there (it was 18 to 22 units in 1000 x 720: 12 to 14 pixels).
constexpr double kFamilyBoxHeight = 118;
void familyBox(Svg& s, const FamilyNode& n) {
    const double h = kFamilyBoxHeight, l = n.centre.x - n.width / 2, t = n.centre.y - h / 2;
    s.rect({l, t}, {l + n.width, t + h}, "#f4f4f4", kInk, 1, 2);
    s.text({n.centre.x, t + 34}, n.name, "middle", 29);
    s.text({n.centre.x, t + 71}, n.paths, "middle", 33, kBsdf);
    s.text({n.centre.x, t + 105}, n.note, "middle", 27, kGrey);
}
// An edge from the bottom of box a to the top of box b, with its label beside its middle.
void familyEdge(Svg& s, const FamilyNode& a, const FamilyNode& b, const char* label, const char* anchor, P offset) {
    const P from = a.centre + P{0, kFamilyBoxHeight / 2}, to = b.centre - P{0, kFamilyBoxHeight / 2};
    s.arrow(from, to, kInk, 3);
    s.text(lerp(from, to, 0.5) + offset, label, anchor, 27, kRed, true);
}
Svg familyTree() {
    // (The caption, "which paths each classic carries", is the lesson text's and the slide's.)
    Svg s(1000, 662);
    const FamilyNode all{
        {500, 60}, 640, "pt, lt, bpt, pm (1986-1996)", "L (D|G|S)* E: all paths", "each with its blind spots (1.17)"};
    const FamilyNode drt{
        {255, 240}, 500, "distributed ray tracing (1984)", "L D? (G|S)* E", "light samples at D and G"};
    const FamilyNode rad{{772, 240}, 440, "radiosity (1984, 1988)", "L D* E", "diffuse quads only"};
    const FamilyNode whitted{{255, 420}, 500, "Whitted (1980)", "L [DG] S* E | L S* E", "point lights only"};
    const FamilyNode common{{500, 600}, 640, "common to all of them", "L D? E", "lamps seen, direct light on D"};
    familyEdge(s, all, drt, "D only next to L", "end", {-20, -8});
    familyEdge(s, all, rad, "only D", "start", {20, -8});
    familyEdge(s, drt, whitted, "G only next to L", "start", {14, 4});
    // Whitted's and radiosity's arrows go straight down onto the common box's top.
    const double top = common.centre.y - kFamilyBoxHeight / 2;
    for (const FamilyNode* n : {&whitted, &rad}) {
        const P from = n->centre + P{0, kFamilyBoxHeight / 2};
        s.arrow(from, {from.x, top}, kInk, 3);
        s.text({from.x + 14, 0.5 * (from.y + top) + 9}, n == &whitted ? "no G, no S" : "one D at most", "start", 27,
               kRed, true);
    }
    for (const FamilyNode* n : {&all, &drt, &rad, &whitted, &common}) familyBox(s, *n);
    return s;
}

}  // namespace

// Lesson 13: a merge and its neighbours in the MIS sum. Top: the light subpath's vertex y_2 lands
// within r of the camera subpath's vertex z_2, and the merge stands for the path x_0 .. x_4 whose
// vertex x_2 is y_2 seen from the light and z_2 seen from the camera (13.1-13.3). Bottom: the
// eight techniques of that path of length 4: five connections (7.7) and three merges (13.6), the
// merge at x_2 with its neighbours: the connections at the edges through x_2 and the merges at x_1
// and x_3.
void techniqueStrip(Svg& s, double bx, double y0, bool merge, int at, int frame, const std::string& caption) {
    // x_0 (light) .. x_4 (camera), left to right.
    P v[] = {{bx + 10, y0}, {bx + 34, y0 + 70}, {bx + 62, y0 + 10}, {bx + 90, y0 + 72}, {bx + 108, y0 + 20}};
    if (frame == 1) s.rect({bx - 4, y0 - 22}, {bx + 114, y0 + 128}, "#fff4d6", "#d98a00", 1, 1.5);
    if (frame == 2) s.rect({bx - 4, y0 - 22}, {bx + 114, y0 + 128}, "none", kInk, 1, 3);
    s.line(v[0] - P{12, 0}, v[0] + P{12, 0}, kLight, 6);
    for (int e = 0; e < 4; ++e) {
        // merge at `at`: edges before x_at are the light's, from x_at on the camera's; connection
        // s = at: edge at-1 -> at is the joining edge.
        const bool lightEdge = merge ? e < at : e + 1 < at;
        const bool joined = !merge && e + 1 == at;
        s.line(v[e], v[e + 1], joined ? kGrey : lightEdge ? kLight : kCamera, 3, joined ? "7 5" : nullptr);
    }
    for (int k = 0; k < 5; ++k) {
        const bool light = merge ? k < at : k < at;
        if (k == 4) s.circle(v[k], 7, light ? kLight : kCamera);
        else s.dot(v[k], light ? kLight : kCamera, 6);
    }
    if (merge) s.circle(v[at], 14, "none", kInk, 1.8);
    s.text({bx + 55, y0 + 112}, caption, "middle", 18, kInk, true);
}

Svg mergeTechniques() {
    Svg s(1000, 700);
    // The merge itself: a surface from (340, 235) to (620, 195), slope -1/7.
    auto onSurface = [](double x) { return P{x, 235 - (x - 340) / 7}; };
    P y0{80, 70}, y1{250, 250}, y2 = onSurface(462), z2 = onSurface(500), z3{690, 90}, z4{900, 190};
    s.line(y0 - P{50, 0}, y0 + P{50, 0}, kLight, 9);
    s.text(y0 + P{0, -16}, "light", "middle", 18, kLight);
    s.circle(z2, 62, "#1f5fbf", kCamera, 1.5, 0.08);
    s.line(onSurface(330), onSurface(640), kInk, 4);  // the surface the merge happens on
    s.line(z2, z2 + P{0, 62}, kGrey, 1.5, "5 4");
    s.text(z2 + P{8, 50}, "r", "start", 20, kGrey, true);
    s.arrow(y0, y1, kLight, 3);
    s.arrow(y1, y2, kLight, 3);
    s.arrow(z4, z3, kCamera, 3);
    s.arrow(z3, z2, kCamera, 3);
    s.dot(y1, kLight, 7);
    s.dot(y2, kLight, 7);
    s.dot(z3, kCamera, 7);
    s.dot(z2, kCamera, 7);
    s.circle(z4, 9, kCamera);
    s.text(y0 + P{-6, 36}, "x_0 = y_0", "end", 20, kInk, true);
    s.text(y1 + P{0, 34}, "x_1 = y_1", "middle", 20, kInk, true);
    s.text(y2 + P{-24, -22}, "y_2", "middle", 20, kLight, true);
    s.text(z2 + P{30, 40}, "z_2", "start", 20, kCamera, true);
    s.text(z3 + P{0, -18}, "x_3 = z_1", "middle", 20, kInk, true);
    s.text(z4 + P{0, 36}, "x_4 = z_0", "middle", 20, kInk, true);
    s.text({560, 310}, "x_2: y_2 seen from the light side, z_2 from the camera side", "middle", 18, kGrey);
    s.text({30, 350},
           "P(‖y_2 − z_2‖ ≤ r) ≈ π r² p_L(x_2)   so   N p_{M,2} = η p_L(x_2) p_{2,3} = η p_E(x_2) p_{3,2},"
           "   η = N π r²",
           "start", 18);
    // The techniques of the path: connections (7.7) and merges (13.6).
    const char* conn[] = {"(0,5)", "(1,4)", "(2,3)", "(3,2)", "(4,1)"};
    for (int c = 0; c < 5; ++c) techniqueStrip(s, 12 + 120 * c, 410, false, c, c == 2 || c == 3 ? 1 : 0, conn[c]);
    const char* merges[] = {"M at x_1", "M at x_2", "M at x_3"};
    for (int m = 0; m < 3; ++m) techniqueStrip(s, 632 + 120 * m, 410, true, m + 1, m == 1 ? 2 : 1, merges[m]);
    s.line({620, 390}, {620, 545}, "#dddddd", 2);
    s.text({30, 590}, "w_{M,2} = (η p_L(x_2) p_{2,3})^b / (the same for all 5 connections and 3 merges)", "start", 18);
    s.text({30, 620}, "framed: the merge at x_2; shaded: its neighbours, which share an edge or an end with it",
           "start", 18, kGrey);
    s.line({30, 670}, {75, 670}, kLight, 3.5);
    s.text({82, 676}, "light subpath", "start", 18);
    s.line({250, 670}, {295, 670}, kCamera, 3.5);
    s.text({302, 676}, "camera subpath", "start", 18);
    s.line({480, 670}, {525, 670}, kGrey, 3.5, "7 5");
    s.text({532, 676}, "connection", "start", 18);
    s.circle({700, 670}, 12, "none", kInk, 1.8);
    s.text({720, 676}, "merge", "start", 18);
    return s;
}

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
    figures.push_back({"01-monte-carlo/low-discrepancy.svg", lowDiscrepancy()});
    figures.push_back({"02-direct-mis/mis-plates.svg", misPlates()});
    figures.push_back({"03-path-tracing/nee-path.svg", neePath()});
    figures.push_back({"04-measurement/pinhole-we.svg", pinholeWe()});
    figures.push_back({"05-light-tracing/light-splat.svg", lightSplat()});
    figures.push_back({"06-path-space/path-vertices.svg", pathVertices()});
    figures.push_back({"07-bidirectional/techniques-k3.svg", bptTechniques()});
    if (!isHeapKdTree()) {
        std::fprintf(stderr, "diagrams: kKdTree is not a kd-tree in heap order\n");
        return 1;
    }
    figures.push_back({"08-photon-mapping/kdtree-query.svg", kdTreeQuery()});
    figures.push_back({"09-metropolis/pss-chain.svg", metropolisChain()});
    figures.push_back({"10-adrrs/weight-window.svg", weightWindow()});
    figures.push_back({"11-classics/family-tree.svg", familyTree()});
    figures.push_back({"12-path-guiding/guiding-field.svg", guidingField()});
    figures.push_back({"13-vcm/merge-techniques.svg", mergeTechniques()});
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
