//! The three levels a hint asks for (ARCHITECTURE decision 4), a leaf every stage may read.
//! The GL's `GL_DONT_CARE` maps to one of them per hint, chosen with the benchmark's
//! figures; `GL_FASTEST` and `GL_NICEST` trade error for speed where a stage has a cheaper
//! or a more exact way (BENCHMARKS.md shows the three side by side).

/// What a hint asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quality {
    /// Documented shortcuts. As the perspective hint (which governs the fragment stage's
    /// precision): blending on narrow color formats reads the destination with a
    /// reciprocal multiply instead of a division (at most 1 ulp off, so within 2 steps of
    /// DONT_CARE). As the fog hint: the factor per vertex. As the
    /// point and line smooth hints: 2 × 2 coverage samples for antialiasing.
    Fastest,
    /// The default: exact perspective, 4 × 4 coverage samples.
    Balanced,
    /// Exact perspective, 8 × 8 coverage samples.
    Nicest,
}

impl Quality {
    /// Coverage samples per pixel side for antialiased points and lines.
    pub fn coverage_samples(self) -> i32 {
        match self {
            Quality::Fastest => 2,
            Quality::Balanced => 4,
            Quality::Nicest => 8,
        }
    }
}
