//! The built-in material library: elastic constants, expansion, conductivity and hardness of
//! common bolted-joint metals, by name, in SI units (Pa, 1/K, W/(m·K), Brinell number HB in
//! kgf/mm²). A scene names one (`material = "steel-304"`) or gives `material = { E, nu }`.
//!
//! Sources: the report (Gould & Mikic 1970, Chapter IV: E = 28·10⁶ psi, ν = 0.3 for its 304
//! steel specimens); otherwise the room-temperature values of the ASM Handbook, Vol. 2
//! (nonferrous alloys) and Vol. 1 (steels), as tabulated by ASM Aerospace Specification
//! Metals / MatWeb for the named temper.
//!
//! # Accuracy
//!
//! Handbook values, typically within a few per cent of a given heat; `tests/scene/units.rs`
//! (`library_steel_304_is_the_reports_constants`) checks 304 steel against the report.
//!
//! # Cost
//!
//! None (a table).
//!
//! ```
//! let al = boltzone::scene::materials::lookup("aluminum-6061-t6").unwrap();
//! assert_eq!(al.name, "aluminium-6061-t6");
//! assert!(al.youngs_modulus > 6e10 && al.youngs_modulus < 8e10);
//! ```

use super::units::{INCH, POUND_FORCE};

/// One library material (SI units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LibraryMaterial {
    /// Name as written in a scene.
    pub name: &'static str,
    /// Young's modulus, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Mean linear thermal expansion 20–100 °C, 1/K.
    pub expansion: f64,
    /// Thermal conductivity at room temperature, W/(m·K).
    pub conductivity: f64,
    /// Brinell hardness HB (kgf/mm², 500 kg load, 10 mm ball).
    pub hardness_hb: f64,
    /// Where the numbers come from.
    pub source: &'static str,
}

const PSI: f64 = POUND_FORCE / (INCH * INCH);

/// The library, in the order listed by `boltzone solve --help`.
pub const LIBRARY: [LibraryMaterial; 6] = [
    // The report's specimens: E and ν from Gould & Mikic 1970 (28e6 psi, 0.3); expansion,
    // conductivity and hardness of annealed AISI 304 from ASM Handbook Vol. 1.
    LibraryMaterial {
        name: "steel-304",
        youngs_modulus: 28.0e6 * PSI,
        poisson_ratio: 0.3,
        expansion: 17.3e-6,
        conductivity: 16.2,
        hardness_hb: 123.0,
        source: "E, nu: Gould & Mikic 1970; others: ASM Handbook Vol. 1, AISI 304 annealed",
    },
    // AISI 1018 cold-drawn carbon steel, ASM Handbook Vol. 1 / MatWeb.
    LibraryMaterial {
        name: "steel-1018",
        youngs_modulus: 205e9,
        poisson_ratio: 0.29,
        expansion: 12.0e-6,
        conductivity: 51.9,
        hardness_hb: 126.0,
        source: "ASM Handbook Vol. 1, AISI 1018 cold drawn (MatWeb)",
    },
    // Aluminium 2024-T3, ASM Aerospace Specification Metals.
    LibraryMaterial {
        name: "aluminium-2024-t3",
        youngs_modulus: 73.1e9,
        poisson_ratio: 0.33,
        expansion: 23.2e-6,
        conductivity: 121.0,
        hardness_hb: 120.0,
        source: "ASM Handbook Vol. 2, 2024-T3 (ASM Aerospace Specification Metals)",
    },
    // Aluminium 6061-T6, ASM Aerospace Specification Metals.
    LibraryMaterial {
        name: "aluminium-6061-t6",
        youngs_modulus: 68.9e9,
        poisson_ratio: 0.33,
        expansion: 23.6e-6,
        conductivity: 167.0,
        hardness_hb: 95.0,
        source: "ASM Handbook Vol. 2, 6061-T6 (ASM Aerospace Specification Metals)",
    },
    // Ti-6Al-4V (grade 5), annealed, ASM Aerospace Specification Metals.
    LibraryMaterial {
        name: "titanium-ti-6al-4v",
        youngs_modulus: 113.8e9,
        poisson_ratio: 0.342,
        expansion: 8.6e-6,
        conductivity: 6.7,
        hardness_hb: 334.0,
        source:
            "ASM Handbook Vol. 2, Ti-6Al-4V grade 5 annealed (ASM Aerospace Specification Metals)",
    },
    // Copper C11000 (electrolytic tough pitch), annealed.
    LibraryMaterial {
        name: "copper-c11000",
        youngs_modulus: 115e9,
        poisson_ratio: 0.31,
        expansion: 17.0e-6,
        conductivity: 388.0,
        hardness_hb: 45.0,
        source: "ASM Handbook Vol. 2, C11000 annealed (MatWeb; HB converted from Rockwell F 40)",
    },
];

/// The library material called `name` (case-insensitive; `aluminum-…` is accepted for
/// `aluminium-…`).
pub fn lookup(name: &str) -> Option<&'static LibraryMaterial> {
    let n = name.to_ascii_lowercase().replace("aluminum", "aluminium");
    LIBRARY.iter().find(|m| m.name == n)
}

/// The names of the library, comma separated (for error messages).
pub fn names() -> String {
    LIBRARY
        .iter()
        .map(|m| m.name)
        .collect::<Vec<_>>()
        .join(", ")
}
