#include "bsdf.h"
#include "sampling.h"

namespace ps {

float fresnelDielectric(float cosThetaI, float etaI, float etaT) {
    cosThetaI = glm::clamp(cosThetaI, 0.0f, 1.0f);
    float sin2T = (etaI / etaT) * (etaI / etaT) * std::max(0.0f, 1.0f - cosThetaI * cosThetaI);
    if (sin2T >= 1.0f) return 1.0f;  // total internal reflection
    float cosThetaT = std::sqrt(1.0f - sin2T);
    float rPar = (etaT * cosThetaI - etaI * cosThetaT) / (etaT * cosThetaI + etaI * cosThetaT);
    float rPerp = (etaI * cosThetaI - etaT * cosThetaT) / (etaI * cosThetaI + etaT * cosThetaT);
    return 0.5f * (rPar * rPar + rPerp * rPerp);
}

namespace {

// Normal flipped to the side of wo (two-sided reflectors).
Vec3 sideNormal(const Vec3& n, const Vec3& wo) { return glm::dot(n, wo) < 0.0f ? -n : n; }

// Phong with exponent 0 is the Lambertian BRDF albedo / pi on the whole hemisphere (cos^0 = 1);
// the lobe about the mirror direction would wrongly cut it off where cos(alpha) <= 0.
bool isLambertian(const Material& m) {
    return m.kind == BSDFKind::Diffuse || (m.kind == BSDFKind::Phong && m.exponent == 0.0f);
}

// Normalized Phong (Lafortune & Willems 1994): f = albedo (n + 2) / (2 pi) cos^n(alpha),
// alpha the angle between wi and the mirror direction of wo. Exponent 0 is Lambertian.
Color phongEval(const Material& m, const Vec3& ns, const Vec3& wo, const Vec3& wi) {
    float cosAlpha = glm::dot(reflect(wo, ns), wi);
    if (cosAlpha <= 0.0f) return Color(0.0f);
    return m.albedo * ((m.exponent + 2.0f) * (0.5f * kInvPi) * std::pow(cosAlpha, m.exponent));
}

}  // namespace

Color evalBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi) {
    if (m.isDelta()) return Color(0.0f);
    const Vec3 ns = sideNormal(n, wo);
    if (glm::dot(ns, wo) <= 0.0f || glm::dot(ns, wi) <= 0.0f) return Color(0.0f);
    if (isLambertian(m)) return m.albedo * kInvPi;
    return phongEval(m, ns, wo, wi);
}

float pdfBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi) {
    if (m.isDelta()) return 0.0f;
    const Vec3 ns = sideNormal(n, wo);
    if (glm::dot(ns, wo) <= 0.0f || glm::dot(ns, wi) <= 0.0f) return 0.0f;
    if (isLambertian(m)) return cosineHemispherePdf(Frame(ns).toLocal(wi));
    return phongLobePdf(Frame(reflect(wo, ns)).toLocal(wi), m.exponent);
}

bool sampleBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec2& u, float uLobe, Transport mode,
                BSDFSample& s) {
    const float cosO = glm::dot(n, wo);
    if (cosO == 0.0f) return false;  // exactly grazing: no valid direction
    const Vec3 ns = cosO < 0.0f ? -n : n;
    switch (isLambertian(m) ? BSDFKind::Diffuse : m.kind) {
    case BSDFKind::Diffuse: {
        const Vec3 local = sampleCosineHemisphere(cosineWarpU(u));  // never the rim
        s.wi = Frame(ns).toWorld(local);
        s.pdf = cosineHemispherePdf(Frame(ns).toLocal(s.wi));  // exactly pdfBSDF(wi)
        if (s.pdf <= 0.0f) return false;
        s.weight = m.albedo;  // (albedo / pi) cos / (cos / pi)
        s.delta = false;
        return true;
    }
    case BSDFKind::Phong: {
        const Vec3 r = reflect(wo, ns);
        const Vec3 local = samplePhongLobe(u, m.exponent);
        s.wi = Frame(r).toWorld(local);
        const float cosI = glm::dot(ns, s.wi);
        if (cosI <= 0.0f) return false;  // lobe direction below the surface: invalid sample
        // The pdf of wi as pdfBSDF evaluates it (not of `local`, whose cos(alpha) differs from
        // the one phongEval recomputes by rounding, amplified by cos^n for large n).
        s.pdf = phongLobePdf(Frame(r).toLocal(s.wi), m.exponent);
        if (s.pdf <= 0.0f) return false;
        s.weight = phongEval(m, ns, wo, s.wi) * cosI / s.pdf;
        s.delta = false;
        return true;
    }
    case BSDFKind::Mirror: {
        s.wi = reflect(wo, ns);
        s.pdf = 1.0f;
        s.weight = m.albedo;
        s.delta = true;
        return true;
    }
    case BSDFKind::Dielectric: {
        const bool entering = cosO > 0.0f;
        const float etaI = entering ? 1.0f : m.ior, etaT = entering ? m.ior : 1.0f;
        const float cosI = std::abs(cosO);
        const float F = fresnelDielectric(cosI, etaI, etaT);
        s.delta = true;
        if (uLobe < F) {  // reflect with probability F: weight F / F = 1
            s.wi = reflect(wo, ns);
            s.pdf = F;
            s.weight = Color(1.0f);
            return true;
        }
        // Refract (Snell): wi on the other side, weight (1 - F) / (1 - F), times the
        // radiance scaling (etaI / etaT)^2 when radiance flows (wo on the etaI side).
        const float eta = etaI / etaT;
        const float cosT = std::sqrt(std::max(0.0f, 1.0f - eta * eta * (1.0f - cosI * cosI)));
        s.wi = glm::normalize(-eta * wo + (eta * cosI - cosT) * ns);
        s.pdf = 1.0f - F;
        s.weight = Color(mode == Transport::Radiance ? eta * eta : 1.0f);
        return true;
    }
    }
    return false;
}

}  // namespace ps
