//! The keys of the simulator window and what they do.

use embedded_graphics_simulator::sdl2::Keycode;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    TogglePixelbuffer,
    ToggleExtents,
    ToggleGrid,
    ToggleSortlist,
    CycleNumber,
    SwitchMode,
    ToggleDither,
    ToggleShadows,
    ToggleOverlay,
    ToggleFill,
    ToggleEdges,
    ToggleProgressive,
    CycleDisplay,
    CycleDepth,
    CycleAntialias,
    SavePng,
    Quit,
}

/// The key help shown in the panel and in docs/simulator.md.
pub const HELP: &[(&str, &str)] = &[
    ("1-4", "pixbuf/extents/grid/sortlist"),
    ("N", "cycle number type"),
    ("M", "PGA / RGB mode"),
    ("D", "dither on/off"),
    ("S", "shadows on/off"),
    ("O", "overlay: extents, grid, plan"),
    ("F", "show Pixelbuffer fill"),
    ("E", "edge image (Roth)"),
    ("C", "progressive (coarse-to-fine)"),
    ("T", "ray tree depth 1..8"),
    ("A", "antialias off/L1..L4"),
    ("L", "cycle display preview"),
    ("P", "save PNG"),
    ("Q/Esc", "quit"),
];

pub fn action(key: Keycode) -> Option<Action> {
    Some(match key {
        Keycode::NUM_1 => Action::TogglePixelbuffer,
        Keycode::NUM_2 => Action::ToggleExtents,
        Keycode::NUM_3 => Action::ToggleGrid,
        Keycode::NUM_4 => Action::ToggleSortlist,
        Keycode::N => Action::CycleNumber,
        Keycode::M => Action::SwitchMode,
        Keycode::D => Action::ToggleDither,
        Keycode::S => Action::ToggleShadows,
        Keycode::O => Action::ToggleOverlay,
        Keycode::F => Action::ToggleFill,
        Keycode::E => Action::ToggleEdges,
        Keycode::C => Action::ToggleProgressive,
        Keycode::L => Action::CycleDisplay,
        Keycode::T => Action::CycleDepth,
        Keycode::A => Action::CycleAntialias,
        Keycode::P => Action::SavePng,
        Keycode::Q | Keycode::Escape => Action::Quit,
        _ => return None,
    })
}

/// The key a character names in `view --keys` (`T`, `a`, `1`: letters either case, digits),
/// if it is one of the window's keys.
pub fn named(character: char) -> Option<Keycode> {
    if !character.is_ascii_alphanumeric() {
        return None;
    }
    // SDL's keycodes for letters and digits are their lower-case ASCII codes.
    let key = Keycode::from_i32(i32::from(character.to_ascii_lowercase() as u8))?;
    action(key).is_some().then_some(key)
}

/// The keys `view --keys` presses, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Script(pub Vec<Keycode>);

/// Parses `view --keys`: one character per key, spaces and commas between them ignored.
pub fn parse_script(text: &str) -> Result<Script, String> {
    text.chars()
        .filter(|c| !c.is_whitespace() && *c != ',')
        .map(|c| named(c).ok_or_else(|| format!("`{c}` is not one of the window's keys (see the key help: 1-4, N, M, D, S, O, F, C, T, A, L, P, Q)")))
        .collect::<Result<_, _>>()
        .map(Script)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_depth_and_antialiasing_keys_are_t_and_a() {
        assert_eq!(action(Keycode::T), Some(Action::CycleDepth));
        assert_eq!(action(Keycode::A), Some(Action::CycleAntialias));
        assert_eq!(action(Keycode::Z), None);
    }

    #[test]
    fn every_key_in_the_help_does_something() {
        for (keys, _) in HELP {
            let first = keys.split(['/', '-']).next().unwrap_or_default();
            let key = if first == "Esc" { Some(Keycode::Escape) } else { first.chars().next().and_then(named) };
            assert!(key.and_then(action).is_some(), "the help's `{keys}` is no key");
        }
        assert!(HELP.iter().any(|(key, _)| *key == "T") && HELP.iter().any(|(key, _)| *key == "A"));
    }

    #[test]
    fn a_script_names_keys_and_rejects_the_rest() {
        assert_eq!(parse_script("tT a,1"), Ok(Script(vec![Keycode::T, Keycode::T, Keycode::A, Keycode::NUM_1])));
        assert_eq!(parse_script(""), Ok(Script(vec![])));
        for bad in ["Z", "TX", "é", "!", "0"] {
            assert!(parse_script(bad).is_err(), "{bad:?} accepted");
        }
    }
}
