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
    ToggleProgressive,
    CycleDisplay,
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
    ("C", "progressive (coarse-to-fine)"),
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
        Keycode::C => Action::ToggleProgressive,
        Keycode::L => Action::CycleDisplay,
        Keycode::P => Action::SavePng,
        Keycode::Q | Keycode::Escape => Action::Quit,
        _ => return None,
    })
}
