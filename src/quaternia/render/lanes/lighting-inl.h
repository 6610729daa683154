// The lighting of a surface point, written once for any number type (section 2.4 of the seed
// paper): Highway SIMD vectors of float in the lanes (shading_lanes.cpp, lightSurfaces) and
// double in the scalar reference and for the extra lights of both engines (shade.cpp,
// Shader::light and Shader::lightOther). The model: Lambert's diffuse and the Blinn-Phong
// highlight of each light, times its factor (intensity, distance, spot cone) and its
// visibility; the key light adds a shadowless fill light and ambient light, both darkened by
// ambient occlusion.
//
// The arithmetic is given by a policy M: M::V the number, and
//   m.set(x)                  a constant
//   m.mulAdd(a, b, c)         a * b + c (fused where the SIMD target fuses)
//   m.max(a, b), m.sqrt(a)
//   m.highlight(gate, cosine) cosine^shininess where gate > 0 and cosine is above the cutoff
//                             below which the power is under 1e-7; 0 elsewhere
// and the operators +, -, *, / on M::V. Every engine thus evaluates the same expressions in the
// same order, and differs only in the precision of its numbers.
//
// Like julia_steps-inl.h, this file has no namespace of its own and is included inside one:
// once per SIMD target by foreach_target (the HWY_TARGET_TOGGLE guard below lets it in again
// for each target), and once into namespace quaternia for the scalar code.

#if defined(QUATERNIA_LIGHTING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_LIGHTING_INL_H_
#undef QUATERNIA_LIGHTING_INL_H_
#else
#define QUATERNIA_LIGHTING_INL_H_
#endif

// Three components of one number type: a unit direction, or a colour.
template <class V>
struct LightVector {
    V x, y, z;
};

template <class M, class V>
inline V lightDot(const M& m, const LightVector<V>& a, const LightVector<V>& b) {
    return m.mulAdd(a.z, b.z, m.mulAdd(a.y, b.y, a.x * b.x));
}

// What one light does at a surface point of unit normal n seen along the unit ray direction
// `view`, the light in the unit direction toLight with the factor `scale`: its diffuse level
// max(0, n . l) scale and its highlight, cos^shininess of the angle between n and the halfway
// vector l - view (normalised by division: no reciprocal of its own).
template <class V>
struct LightLevels {
    V diffuse, highlight;
};
template <class M, class V>
inline LightLevels<V> blinnPhong(const M& m, const LightVector<V>& n, const LightVector<V>& toLight,
                                 const LightVector<V>& view, V scale) {
    const V diffuse = m.max(m.set(0), lightDot(m, n, toLight)) * scale;
    const LightVector<V> halfway{toLight.x - view.x, toLight.y - view.y, toLight.z - view.z};
    const V cosine = lightDot(m, n, halfway) / m.sqrt(lightDot(m, halfway, halfway));
    return {diffuse, m.highlight(diffuse, cosine)};
}

// The key light with the fill and ambient light, one colour channel: the albedo `base` under
// the direct light (diffuse times visibility) and the fill and ambient levels (times the
// openness), plus the highlight in the light's colour.
template <class M, class V>
inline V keyLitChannel(const M& m, V base, V direct, V shine, V fillLevel, V ambientLevel,
                       V lightColor, V fillColor) {
    const V lit = m.mulAdd(direct, lightColor, m.mulAdd(fillLevel, fillColor, ambientLevel));
    return m.mulAdd(base, lit, shine * lightColor);
}

// The key light at a surface point, all three channels (Shader::light, lightSurfaces):
// `specular` the highlight's strength, visibility of the key light, occlusion the openness
// that darkens the fill and ambient light.
template <class M, class V>
inline LightVector<V> litByKey(const M& m, const LightVector<V>& n, const LightVector<V>& toLight,
                               const LightVector<V>& view, V keyScale, V visibility, V occlusion,
                               const LightVector<V>& albedo, const LightVector<V>& fill,
                               const LightVector<V>& lightColor, const LightVector<V>& fillColor,
                               V specular, V ambient) {
    const LightLevels<V> key = blinnPhong(m, n, toLight, view, keyScale);
    const V fillDiffuse = m.max(m.set(0), lightDot(m, n, fill));
    const V direct = key.diffuse * visibility;
    const V shine = specular * key.highlight * keyScale * visibility;
    const V fillLevel = fillDiffuse * occlusion, ambientLevel = ambient * occlusion;
    return {keyLitChannel(m, albedo.x, direct, shine, fillLevel, ambientLevel, lightColor.x,
                          fillColor.x),
            keyLitChannel(m, albedo.y, direct, shine, fillLevel, ambientLevel, lightColor.y,
                          fillColor.y),
            keyLitChannel(m, albedo.z, direct, shine, fillLevel, ambientLevel, lightColor.z,
                          fillColor.z)};
}

// What a light other than the key adds (Shader::lightOther): its diffuse light on the albedo and
// its highlight, in its colour, times its visibility; no fill or ambient light of its own.
template <class M, class V>
inline LightVector<V> litByOther(const M& m, const LightVector<V>& n, const LightVector<V>& toLight,
                                 const LightVector<V>& view, V scale, V visibility,
                                 const LightVector<V>& albedo, const LightVector<V>& color,
                                 V specular) {
    const LightLevels<V> light = blinnPhong(m, n, toLight, view, scale);
    const V direct = light.diffuse * visibility;
    const V shine = specular * light.highlight * scale * visibility;
    return {m.mulAdd(albedo.x, direct * color.x, shine * color.x),
            m.mulAdd(albedo.y, direct * color.y, shine * color.y),
            m.mulAdd(albedo.z, direct * color.z, shine * color.z)};
}

#endif  // QUATERNIA_LIGHTING_INL_H_
