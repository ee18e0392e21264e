//! `microtrace bench --thesis`: not written yet.

pub fn run(_args: &super::BenchArgs) -> anyhow::Result<()> {
    anyhow::bail!("bench --thesis is not implemented yet")
}
