//! Which of the four screen-space optimizations of §4.7 a scene turns on.

/// Which of the four optimizations of §4.7 are on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Optimizations {
    pub pixelbuffer: bool,
    pub extents: bool,
    pub grid: bool,
    pub sortlist: bool,
}

impl Optimizations {
    pub const ALL: Self = Self { pixelbuffer: true, extents: true, grid: true, sortlist: true };
    pub const NONE: Self = Self { pixelbuffer: false, extents: false, grid: false, sortlist: false };

    /// `all`, `none`, or a comma-separated list of `pixelbuffer`, `extents`, `grid` and
    /// `sortlist` (the command line's `--opt` and the firmware build's `MICROTRACE_OPT`);
    /// `Err` holds the first unknown name.
    pub fn from_list(text: &str) -> Result<Self, &str> {
        match text {
            "all" => return Ok(Self::ALL),
            "none" => return Ok(Self::NONE),
            _ => {}
        }
        let mut chosen = Self::NONE;
        for word in text.split(',') {
            match word.trim() {
                "pixelbuffer" => chosen.pixelbuffer = true,
                "extents" => chosen.extents = true,
                "grid" => chosen.grid = true,
                "sortlist" => chosen.sortlist = true,
                other => return Err(other),
            }
        }
        Ok(chosen)
    }

    /// All 16 combinations, `NONE` first.
    pub fn combinations() -> impl Iterator<Item = Self> {
        (0u8..16).map(|bits| Self {
            pixelbuffer: bits & 1 != 0,
            extents: bits & 2 != 0,
            grid: bits & 4 != 0,
            sortlist: bits & 8 != 0,
        })
    }
}

