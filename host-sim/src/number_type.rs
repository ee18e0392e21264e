//! The number types on the command line: the core's [`NumberKind`] (the one switch from a name
//! to a type, `microtrace::with_number_kind!`) offered as `--number`'s values.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use microtrace::number::NumberKind;

/// `--number`'s parser: the kinds' names, each with its summary in `--help`.
pub fn number_kind_parser() -> impl TypedValueParser<Value = NumberKind> {
    PossibleValuesParser::new(NumberKind::ALL.map(|kind| PossibleValue::new(kind.name()).help(kind.summary())))
        // The possible values are exactly the kinds' names, so every parsed name has a kind.
        .map(|name| NumberKind::from_name(&name).unwrap_or(NumberKind::F64))
}

#[cfg(test)]
mod tests {
    use super::number_kind_parser;
    use clap::builder::TypedValueParser;
    use microtrace::number::NumberKind;

    #[test]
    fn command_line_names_are_the_core_type_names() {
        let parser = number_kind_parser();
        let offered: Vec<String> = parser.possible_values().expect("the names are listed").map(|value| value.get_name().to_owned()).collect();
        let names: Vec<&str> = NumberKind::ALL.iter().map(|n| n.name()).collect();
        assert_eq!(offered, names);
        assert_eq!(names, ["f64", "f32", "fixed", "fixed16", "f32-micromath", "soft32"]);
    }
}
