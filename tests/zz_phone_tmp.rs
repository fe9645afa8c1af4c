use roughtui::figure::{render_phone, FigureOptions, View, Withheld, UPRIGHT, WIDE};
#[test]
fn write() {
    for (name, shape) in [("up", UPRIGHT), ("wide", WIDE)] {
        for p in ["fig2", "fig3"] {
            let s = roughtui::presets::load(p).unwrap();
            for v in [View::Slopes, View::Indices, View::Map, View::Load] {
                let mut o = FigureOptions::default();
                let pic = render_phone(v, &s, &o, shape).unwrap();
                std::fs::write(format!("/tmp/ph-{p}-{}-{name}.svg", v.name()), &pic.svg).unwrap();
                o.withheld = Withheld {
                    marks: true,
                    slopes: [false, true, true, false],
                    indices: [false, false, true, true],
                };
                let pic = render_phone(v, &s, &o, shape).unwrap();
                std::fs::write(format!("/tmp/ph-{p}-{}-{name}-w.svg", v.name()), &pic.svg).unwrap();
                eprintln!(
                    "{p} {} {name} {} {:?}",
                    v.name(),
                    pic.svg.len(),
                    pic.legend
                        .iter()
                        .map(|e| e.label.clone())
                        .collect::<Vec<_>>()
                );
            }
        }
    }
}
