use quadsect::bench_cases::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(|s| s.as_str()).unwrap_or("issue");
    let reps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let c = match which {
        "issue" => issue_example(),
        "rotq" => rotated_quartic()[0].clone(),
        "rotqe" => rotated_quartic()[1].clone(),
        "d5" => dense_cases(5)[0].clone(),
        "d5r" => dense_cases(5)[1].clone(),
        "d6" => dense_cases(6)[0].clone(),
        "d6r" => dense_cases(6)[1].clone(),
        "d8" => dense_cases(8)[0].clone(),
        "c300" => big_cubic(300),
        "c3" => big_cubic(3),
        p => quartic_pairs()[p.parse::<usize>().unwrap()].clone(),
    };
    for _ in 0..reps {
        let t = std::time::Instant::now();
        let r = quadsect::tangent::decide(&c.e, &c.s).unwrap();
        let el = t.elapsed();
        let extra = match &r.certificate.method {
            quadsect::tangent::Method::ModularRur(an) => format!(
                "N={} primes={} fbits={} gbits={} dbits={}",
                an.rur.points(),
                an.rur.primes,
                an.rur.f.coeffs().iter().map(|c| c.bits()).max().unwrap(),
                an.rur
                    .coords
                    .iter()
                    .flat_map(|g| g.coeffs().iter().map(|c| c.bits()))
                    .max()
                    .unwrap(),
                an.rur
                    .denom
                    .coeffs()
                    .iter()
                    .map(|c| c.bits())
                    .max()
                    .unwrap()
            ),
            _ => String::new(),
        };
        println!(
            "{} {:?} {} {:?} {}",
            c.id,
            r.verdict,
            method_name(&r),
            el,
            extra
        );
    }
}
