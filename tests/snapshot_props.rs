//! Properties: every valid state survives save → load bit for bit; no input,
//! however mangled, makes loading panic.

use proptest::prelude::*;
use proptest::sample::select;
use rough_model::{Axis, Model, Moments, ParamValues, Params, Sweep};
use roughtui::scene::State;
use roughtui::snapshot::{load_file, save_new};

/// Positive finite values, subnormals and extremes included.
fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![
        prop::num::f64::POSITIVE | prop::num::f64::NORMAL | prop::num::f64::SUBNORMAL,
        (-320.0f64..308.0)
            .prop_map(|e| 10f64.powf(e))
            .prop_filter("finite, > 0", |v| v.is_finite() && *v > 0.0),
        select(vec![
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            1e-300,
            0.1,
            1.0 / 3.0
        ]),
    ]
}

fn at_least_one() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1.0),
        positive()
            .prop_map(|v| if v < 1.0 { 1.0 / v } else { v })
            .prop_filter("finite", |v| v.is_finite()),
        Just(f64::MAX),
        Just(1.0 + f64::EPSILON),
    ]
}

fn hurst() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1.0),
        positive().prop_filter("<= 1", |v| *v <= 1.0),
        (0.0f64..1.0).prop_filter("> 0", |v| *v > 0.0),
    ]
}

fn non_negative() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(-0.0), positive()]
}

/// A value in the domain of `axis`, > 0 (sweep ends on log axes).
fn on_axis(axis: Axis) -> BoxedStrategy<f64> {
    match axis {
        Axis::Zeta => at_least_one().boxed(),
        Axis::Hurst => hurst().boxed(),
        _ => positive().boxed(),
    }
}

fn sweep() -> impl Strategy<Value = Sweep> {
    select(Axis::ALL.to_vec())
        .prop_flat_map(|a| (Just(a), on_axis(a), on_axis(a)))
        .prop_filter_map("from < to", |(a, x, y)| {
            Sweep::new(a, x.min(y), x.max(y)).ok()
        })
}

fn state() -> impl Strategy<Value = State> {
    (
        "[^\\p{Cc}]{0,64}",
        (
            positive(),
            positive(),
            at_least_one(),
            hurst(),
            non_negative(),
            positive(),
        ),
        any::<bool>(),
        sweep(),
        prop_oneof![Just(Model::Exact), Just(Model::ClosedForm)],
        // Quotes, backslashes and non-ASCII text included.
        prop::option::of("[^\\p{Cc}]{0,300}"),
        prop_oneof![Just(Moments::Truncated), Just(Moments::Asymptotic)],
    )
        .prop_map(
            |(
                name,
                (h0_over_e, h_rms, zeta, hurst, r_star, q0),
                size_effect,
                sweep,
                model,
                caption,
                moments,
            )| {
                let params = Params::new(ParamValues {
                    h0_over_e,
                    h_rms,
                    zeta,
                    hurst,
                    r_star,
                    q0,
                })
                .expect("generated in the domain");
                // H = 1 has no asymptotic moments: such a state is refused.
                let moments = if hurst == 1.0 {
                    Moments::Truncated
                } else {
                    moments
                };
                State {
                    name,
                    caption,
                    params,
                    size_effect,
                    sweep,
                    model,
                    moments,
                    surface: None,
                    seed: None,
                    shown: Default::default(),
                }
            },
        )
}

/// Every float compared by its bits (so -0.0 and 0.0 differ).
type Bits = (String, Option<String>, [u64; 8], bool, Axis, Model, Moments);

fn bits(s: &State) -> Bits {
    let v = s.params.values();
    let f = [
        v.h0_over_e,
        v.h_rms,
        v.zeta,
        v.hurst,
        v.r_star,
        v.q0,
        s.sweep.from(),
        s.sweep.to(),
    ];
    (
        s.name.clone(),
        s.caption.clone(),
        f.map(f64::to_bits),
        s.size_effect,
        s.sweep.axis(),
        s.model,
        s.moments,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn to_ron_from_ron_is_bit_exact(s in state()) {
        let back = State::from_ron(&s.to_ron()).map_err(|e| TestCaseError::fail(format!("{e}\n{}", s.to_ron())))?;
        prop_assert_eq!(bits(&back), bits(&s));
    }

    #[test]
    fn save_new_load_file_is_bit_exact(s in state()) {
        let dir = tempfile::tempdir().unwrap();
        let p = save_new(dir.path(), "prop", &s).unwrap();
        let back = load_file(&p).unwrap();
        prop_assert_eq!(bits(&back), bits(&s));
    }

    #[test]
    fn random_bytes_never_panic(b in prop::collection::vec(any::<u8>(), 0..4096)) {
        let _ = State::from_bytes(&b);
    }

    #[test]
    fn mutated_snapshots_never_panic(
        s in state(),
        edits in prop::collection::vec((0usize..4, any::<prop::sample::Index>(), 0usize..TOKENS.len(), any::<u8>()), 1..8),
    ) {
        let mut b = s.to_ron().into_bytes();
        for (op, at, tok, byte) in edits {
            let i = if b.is_empty() { 0 } else { at.index(b.len()) };
            match op {
                0 if !b.is_empty() => b[i] ^= byte | 1,
                1 => b.truncate(i),
                2 => { b.splice(i..i, TOKENS[tok].bytes()); }
                _ if !b.is_empty() => { b.remove(i); }
                _ => b.push(byte),
            }
        }
        // Ok or Err, never a panic; anything accepted must save and load again.
        if let Ok(st) = State::from_bytes(&b) {
            let back = State::from_ron(&st.to_ron()).unwrap();
            prop_assert_eq!(bits(&back), bits(&st));
        }
    }
}

const TOKENS: [&str; 23] = [
    "(",
    ")",
    "[",
    "]",
    ",",
    ":",
    "\"",
    "r#\"",
    "/*",
    "*/",
    "//",
    "NaN",
    "inf",
    "-",
    "1e999",
    "Zeta",
    "ClosedForm",
    "\\u{1b}",
    "\u{feff}",
    "version: 2,",
    "caption: \"",
    "moments: Asymptotic,",
    "hurst: 1.0,",
];
