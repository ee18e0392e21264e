//! Robustness of the `.mts` parser against hostile input: arbitrary bytes, token soup, random
//! mutations of the thesis scenes, huge numbers and 10 MB lines. Deterministic (xorshift), so a
//! failure reproduces; every input must either parse into a scene that satisfies the format's
//! invariants or fail with an error whose line is within the input and whose message is not
//! empty. A panic prints the offending input.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use microtrace::model::{SceneError, SceneErrorKind};
use microtrace::parser::parse;
use microtrace::model::{Light, Projection, SceneDescription};

const CAPACITY: usize = 512;
type Scene = SceneDescription<CAPACITY>;

const SNOOKER: &[u8] = include_bytes!("../../scenes/snooker.mts");
const LATTICE: &[u8] = include_bytes!("../../scenes/lattice.mts");

/// Runs `f` on a thread with a large stack (a `SceneDescription<512>` is ~100 KB).
fn on_big_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new().stack_size(64 << 20).spawn(f).unwrap().join().unwrap();
}

/// xorshift64*: small, fast, deterministic.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
    fn pick_str(&mut self, items: &[&'static str]) -> &'static str {
        items[self.below(items.len())]
    }
}

fn preview(input: &[u8]) -> String {
    let shown = &input[..input.len().min(2000)];
    format!("{:?}{}", String::from_utf8_lossy(shown), if input.len() > 2000 { " ..." } else { "" })
}

/// How a parse ended, for the coverage counters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Outcome {
    Parsed,
    Rejected,
}

/// Parses `input`, checks every invariant, and reports the outcome.
fn check(input: &[u8]) -> Outcome {
    let result = catch_unwind(AssertUnwindSafe(|| parse::<CAPACITY>(input)));
    let result = match result {
        Ok(result) => result,
        Err(_) => panic!("the parser panicked on {}", preview(input)),
    };
    let lines = input.iter().filter(|&&b| b == b'\n').count() as u64 + 1;
    match result {
        Ok(scene) => {
            check_scene(&scene, lines, input);
            Outcome::Parsed
        }
        Err(error) => {
            check_error(&error, lines, input);
            Outcome::Rejected
        }
    }
}

fn check_error(error: &SceneError, lines: u64, input: &[u8]) {
    assert!(
        error.line >= 1 && u64::from(error.line) <= lines + 1,
        "error line {} outside 1..={} for {}",
        error.line,
        lines + 1,
        preview(input)
    );
    let message = error.to_string();
    let prefix = format!("line {}: ", error.line);
    assert!(message.starts_with(&prefix), "{message}");
    assert!(message.len() > prefix.len() + 3, "empty message {message:?} for {}", preview(input));
    assert!(message.len() < 400, "overlong message {message:?}");
    assert!(!matches!(
        error.kind,
        SceneErrorKind::PrimitiveNotCompiled { .. } | SceneErrorKind::OutOfRangeForNumberType { .. }
    ));
}

fn finite(v: [f64; 3]) -> bool {
    v.iter().all(|c| c.is_finite())
}

fn nonzero_length(v: [f64; 3]) -> bool {
    let length = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    length > 0.0 && length.is_finite()
}

fn check_scene(scene: &Scene, lines: u64, input: &[u8]) {
    let what = || preview(input);
    let v = scene.viewport;
    assert!(v.x1 <= v.x2 && v.y1 <= v.y2 && v.x2 <= 32767 && v.y2 <= 32767, "{v:?} {}", what());
    let w = scene.window;
    assert!(w.x1 < w.x2 && w.y1 < w.y2 && (w.x2 - w.x1).is_finite() && (w.y2 - w.y1).is_finite(), "{}", what());
    assert!(scene.view_plane.is_finite());
    match scene.projection {
        Projection::Parallel { direction } => assert!(nonzero_length(direction), "{}", what()),
        Projection::Perspective { eye } => assert!(finite(eye)),
    }
    match scene.light {
        Light::Direction(direction) => assert!(nonzero_length(direction), "{}", what()),
        Light::Point(position) => assert!(finite(position)),
    }
    assert!(scene.ambient >= 0.0 && scene.ambient.is_finite());
    assert!(scene.palette.entries.iter().all(|e| e.r <= 15 && e.g <= 15 && e.b <= 15));
    let mut previous_line = 0;
    for object in &scene.objects {
        assert!(object.line > previous_line && u64::from(object.line) <= lines, "{}", what());
        previous_line = object.line;
        assert!(object.world_from_object.affine_inverse().is_some(), "singular object accepted: {}", what());
        let m = &object.material;
        assert!(m.colour <= 15);
        for k in [m.ka, m.kd, m.ks, m.rnd] {
            assert!(k >= 0.0 && k.is_finite(), "{}", what());
        }
        assert!((0.0..=1.0e6).contains(&m.pwr));
        assert!(m.cmy.iter().all(|c| (0.0..=1.0).contains(c)));
    }
}

const KEYWORDS: &[&str] = &[
    "viewport", "window", "viewplane", "perspective", "parallel", "light", "ambient", "background", "shadows",
    "dither", "group", "optimize", "cube", "sphere", "cylinder", "cone", "scale", "rotate", "translate", "colour",
    "ka", "kd", "ks", "pwr", "rnd", "cmy",
];

const WORDS: &[&str] = &[
    "on", "off", "up", "down", "point", "direction", "x", "y", "z", "w", "all", "none", "pixelbuffer", "extents",
    "grid", "sortlist", "maybe", "inf", "nan", "#", "Sphere", "é", "\u{1b}",
];

const NUMBERS: &[&str] = &[
    "0", "1", "-1", "2", "15", "16", "255", "256", "32767", "32768", "0.5", "-0.5", "1e3", "1e-3", "1e400", "-1e400",
    "1e-400", "1.5", "100", "-0", "0.0", "1.", ".5", "1e", "+2", "1e308", "1e-200", "1e200", "90", "-90", "1e6",
    "1000001", "0x10", "1,5", "7e-1", "123456789012345678901234567890",
];

/// A number or word argument, sometimes nonsense.
fn argument(rng: &mut Rng) -> String {
    match rng.below(10) {
        0..=6 => rng.pick(NUMBERS).to_string(),
        7..=8 => rng.pick(WORDS).to_string(),
        _ => {
            let digits = 1 + rng.below(40);
            let mut s: String = (0..digits).map(|_| char::from(b'0' + rng.below(10) as u8)).collect();
            if rng.below(2) == 0 {
                s.insert(0, '-');
            }
            if rng.below(3) == 0 {
                s.push_str(&format!("e{}", rng.below(700) as i64 - 350));
            }
            s
        }
    }
}

/// A random line: mostly a keyword with 0..=6 arguments, sometimes a comment or blank.
fn statement(rng: &mut Rng) -> String {
    let mut line = String::new();
    match rng.below(12) {
        0 => line.push_str("# a comment"),
        1 => {}
        _ => {
            line.push_str(rng.pick_str(KEYWORDS));
            let count = rng.below(7);
            for _ in 0..count {
                line.push_str(if rng.below(8) == 0 { "\t" } else { " " });
                line.push_str(&argument(rng));
            }
        }
    }
    if rng.below(10) == 0 {
        line.push_str(" # trailing");
    }
    line.push_str(if rng.below(6) == 0 { "\r\n" } else { "\n" });
    line
}

#[test]
fn unmodified_thesis_scenes_parse() {
    on_big_stack(|| {
        let snooker: Scene = parse(SNOOKER).unwrap();
        assert_eq!(snooker.objects.len(), 21);
        let lattice: Scene = parse(LATTICE).unwrap();
        assert_eq!(lattice.objects.len(), 54);
        assert_eq!(check(SNOOKER), Outcome::Parsed);
        assert_eq!(check(LATTICE), Outcome::Parsed);
        // Too small a build names its capacity on the first object that does not fit.
        let error = parse::<20>(SNOOKER).unwrap_err();
        assert_eq!(error.kind, SceneErrorKind::TooManyObjects { capacity: 20 });
        assert!(error.to_string().contains("at most 20"), "{error}");
    });
}

#[test]
fn arbitrary_bytes() {
    on_big_stack(|| {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let alphabet = b"0123456789 .-+eE#\t\r\n\n\n\xff\xc3\xa9x";
        for round in 0..100_000 {
            let length = rng.below(if round % 100 == 0 { 4000 } else { 120 });
            let input: Vec<u8> = (0..length)
                .map(|_| if rng.below(2) == 0 { rng.next() as u8 } else { *rng.pick(alphabet) })
                .collect();
            check(&input);
            // The same bytes after a valid prefix, so they land in argument positions too.
            let prefix = format!("{} ", rng.pick(KEYWORDS));
            let mut prefixed = prefix.into_bytes();
            prefixed.extend_from_slice(&input);
            check(&prefixed);
        }
    });
}

#[test]
fn token_soup() {
    on_big_stack(|| {
        let mut rng = Rng(0xD1B5_4A32_D192_ED03);
        let (mut parsed, mut rejected) = (0, 0);
        for _ in 0..150_000 {
            let mut text = String::new();
            // Usually start with an object so object statements are reachable.
            if rng.below(4) != 0 {
                text.push_str(rng.pick_str(&["sphere\n", "cube\n", "cylinder\n", "cone\n"]));
            }
            for _ in 0..rng.below(8) {
                text.push_str(&statement(&mut rng));
            }
            match check(text.as_bytes()) {
                Outcome::Parsed => parsed += 1,
                Outcome::Rejected => rejected += 1,
            }
        }
        // Both paths must be exercised for the test to mean anything.
        eprintln!("token soup: parsed {parsed}, rejected {rejected}");
        assert!(parsed > 5_000 && rejected > 5_000, "parsed {parsed}, rejected {rejected}");
    });
}

/// One random edit: flip, insert or delete a byte, or duplicate, delete or swap a line.
fn mutate(rng: &mut Rng, text: &mut Vec<u8>) {
    let interesting = b" \t\n\r#.-e0159\xff\x00";
    match rng.below(7) {
        0 if !text.is_empty() => {
            let at = rng.below(text.len());
            text[at] ^= 1 << rng.below(8);
        }
        1 => {
            let at = rng.below(text.len() + 1);
            let byte = if rng.below(2) == 0 { rng.next() as u8 } else { *rng.pick(interesting) };
            text.insert(at, byte);
        }
        2 if !text.is_empty() => {
            let at = rng.below(text.len());
            text.remove(at);
        }
        3..=6 => {
            let mut lines: Vec<Vec<u8>> = text.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
            let a = rng.below(lines.len());
            let b = rng.below(lines.len());
            match rng.below(3) {
                0 => {
                    let copy = lines[a].clone();
                    lines.insert(b, copy);
                }
                1 if lines.len() > 1 => {
                    lines.remove(a);
                }
                _ => lines.swap(a, b),
            }
            *text = lines.join(&b'\n');
        }
        _ => {}
    }
}

#[test]
fn mutated_thesis_scenes() {
    on_big_stack(|| {
        let mut rng = Rng(0x0123_4567_89AB_CDEF);
        let (mut parsed, mut rejected) = (0, 0);
        for round in 0..30_000 {
            let mut text = if round % 2 == 0 { SNOOKER.to_vec() } else { LATTICE.to_vec() };
            for _ in 0..1 + rng.below(6) {
                mutate(&mut rng, &mut text);
            }
            match check(&text) {
                Outcome::Parsed => parsed += 1,
                Outcome::Rejected => rejected += 1,
            }
        }
        eprintln!("mutations: parsed {parsed}, rejected {rejected}");
        assert!(parsed > 1_000 && rejected > 1_000, "parsed {parsed}, rejected {rejected}");
    });
}

#[test]
fn huge_and_tiny_numbers_in_every_position() {
    on_big_stack(|| {
        let long_digits = "9".repeat(100_000);
        let long_fraction = format!("0.{}", "0".repeat(100_000));
        let huge: Vec<String> = vec![
            "1e400".into(),
            "-1e400".into(),
            "1e-400".into(),
            "1e99999999999999999999999999999".into(),
            "1e-99999999999999999999999999999".into(),
            "-0e99999999999999999999999".into(),
            "1.7976931348623157e308".into(),
            "1.7976931348623159e308".into(),
            "4.9e-324".into(),
            "32767.00000000000000000000001".into(),
            "15e0".into(),
            "0.15e2".into(),
            long_digits.clone(),
            format!("-{long_digits}"),
            long_fraction.clone(),
            format!("{long_fraction}1"),
            format!("1{}e-100000", "0".repeat(100_000)),
        ];
        let templates = [
            "viewport {} 10 0 10", "viewport 0 {} 0 32767", "window {} 1 0 1", "window -1 1 -1 {}", "viewplane {}",
            "perspective {} 0 0", "parallel 0 {} 0", "light point 0 0 {}", "light direction {} 0 0", "ambient {}",
            "background {}", "group {} 1 1 1 up", "group 1 1 {} 1 down", "sphere\nscale {} 1 1",
            "sphere\nscale 1 {} {}", "sphere\nrotate x {}", "sphere\ntranslate {} 0 0", "sphere\ncolour {}",
            "sphere\nka {}", "sphere\nkd {}", "sphere\nks {}", "sphere\npwr {}", "sphere\nrnd {}", "sphere\ncmy {} 0 0",
        ];
        for template in templates {
            for number in &huge {
                check(template.replace("{}", number).as_bytes());
            }
        }
    });
}

/// A named family of inputs, built at a given size.
type LineCase = (&'static str, Box<dyn Fn(usize) -> Vec<u8>>);

/// Parses and checks `input`, returning how long the parse took.
fn timed(input: &[u8]) -> Duration {
    let start = Instant::now();
    check(input);
    start.elapsed()
}

#[test]
fn ten_megabyte_lines_take_linear_time() {
    on_big_stack(|| {
        const TEN_MB: usize = 10 << 20;
        let cases: Vec<LineCase> = vec![
            ("a long number", Box::new(|n| format!("viewplane {}", "9".repeat(n)).into_bytes())),
            ("a long fraction", Box::new(|n| format!("viewplane 1.{}", "3".repeat(n)).into_bytes())),
            ("a long exponent", Box::new(|n| format!("background 1e{}", "1".repeat(n)).into_bytes())),
            ("a long integer check", Box::new(|n| format!("background 1{}e-{}", "0".repeat(n), n).into_bytes())),
            ("many arguments", Box::new(|n| format!("viewport {}", "1 ".repeat(n / 2)).into_bytes())),
            ("many optimize words", Box::new(|n| format!("optimize {}fast", "grid ".repeat(n / 5)).into_bytes())),
            ("a long keyword", Box::new(|n| "x".repeat(n).into_bytes())),
            ("a long comment", Box::new(|n| format!("sphere #{}", "\u{ff}".repeat(n / 2)).into_bytes())),
            ("invalid UTF-8", Box::new(|n| vec![0xff; n])),
            ("blank space", Box::new(|n| format!("{}sphere", " \t".repeat(n / 2)).into_bytes())),
            ("many empty lines", Box::new(|n| format!("{}bogus", "\r\n".repeat(n / 2)).into_bytes())),
            ("many statements", Box::new(|n| format!("sphere\n{}", "kd 0.5\n".repeat(n / 7)).into_bytes())),
            ("many objects", Box::new(|n| "cube\n".repeat(n / 5).into_bytes())),
        ];
        for (name, make) in &cases {
            let small = timed(&make(TEN_MB / 10));
            let large = timed(&make(TEN_MB));
            eprintln!("{name}: 1 MB {small:?}, 10 MB {large:?}");
            // Ten times the input may take at most ~30 times as long (plus noise), and
            // 10 MB must stay well under a couple of seconds even in a slow build.
            assert!(
                large <= small * 40 + Duration::from_millis(500),
                "{name}: 1 MB took {small:?} but 10 MB took {large:?}"
            );
            assert!(large < Duration::from_secs(5), "{name}: 10 MB took {large:?}");
        }
    });
}
