//! What the benches share: one deterministic generator of inputs, the median of timed runs,
//! and the directory their summaries go to. (The cubic as lyon_geom's segment is in
//! `lyon.rs`, for the benches that depend on lyon_geom.)

/// SplitMix64 in [0, 1).
pub struct Rng(pub u64);

impl Rng {
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A 3-D point in [-1, 1]^3.
    #[allow(dead_code)]
    pub fn point(&mut self) -> [f64; 3] {
        std::array::from_fn(|_| 2.0 * self.unit() - 1.0)
    }
}

/// The median over `runs` runs of `f`, in seconds.
#[allow(dead_code)]
pub fn median_time(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let start = std::time::Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[runs / 2]
}

/// `$CARGO_TARGET_DIR/name` (else `target/name` of the root crate), created.
#[allow(dead_code)]
pub fn out_dir(name: &str) -> std::path::PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"));
    let dir = target.join(name);
    std::fs::create_dir_all(&dir).expect("a writable target directory");
    dir
}
