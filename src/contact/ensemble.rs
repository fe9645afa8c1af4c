//! Realisations over seeds: the mean and the sample standard deviation of
//! each simulated quantity, so that one realisation is not taken for the
//! answer.

/// Consecutive seeds `first`, `first + 1`, … (`count` of them).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Seeds {
    pub first: u64,
    pub count: u32,
}

impl Seeds {
    pub fn one(seed: u64) -> Seeds {
        Seeds {
            first: seed,
            count: 1,
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = u64> {
        let first = self.first;
        (0..u64::from(self.count)).map(move |k| first.wrapping_add(k))
    }

    /// "seed 1", "seeds 1–4".
    pub fn words(&self) -> String {
        if self.count <= 1 {
            format!("seed {}", self.first)
        } else {
            format!(
                "seeds {}–{}",
                self.first,
                self.first.wrapping_add(u64::from(self.count) - 1)
            )
        }
    }
}

/// Mean and sample standard deviation of a quantity over realisations.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stat {
    pub mean: f64,
    /// Sample standard deviation (n − 1); NaN for one value.
    pub sd: f64,
    pub n: usize,
}

impl Stat {
    /// Of `values` (NaN entries — no contact — left out of both).
    pub fn of(values: impl IntoIterator<Item = f64>) -> Stat {
        let v: Vec<f64> = values.into_iter().filter(|x| !x.is_nan()).collect();
        let n = v.len();
        if n == 0 {
            return Stat {
                mean: f64::NAN,
                sd: f64::NAN,
                n,
            };
        }
        let mean = v.iter().sum::<f64>() / n as f64;
        let sd = if n > 1 {
            (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            f64::NAN
        };
        Stat { mean, sd, n }
    }

    /// The standard error of the mean, sd/√n.
    pub fn sem(&self) -> f64 {
        self.sd / (self.n as f64).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_and_sample_deviation() {
        let s = Stat::of([1.0, 2.0, 3.0, 4.0]);
        assert_eq!(s.mean, 2.5);
        assert!((s.sd - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!(s.n, 4);
        let one = Stat::of([7.0]);
        assert_eq!(one.mean, 7.0);
        assert!(one.sd.is_nan());
        assert_eq!(Stat::of([f64::NAN, 1.0, 3.0]).mean, 2.0);
        assert_eq!(
            Seeds { first: 3, count: 4 }.iter().collect::<Vec<_>>(),
            [3, 4, 5, 6]
        );
        assert_eq!(Seeds::one(5).words(), "seed 5");
    }
}
