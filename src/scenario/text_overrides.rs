//! `--set KEY=VALUE` on a scenario: the file's text is edited (the key's value replaced, or
//! the key added to its table), so errors still point at lines of the scenario as run.

use anyhow::{Context, bail};

/// Marks a line written by `--set`; the item follows, so errors can name it.
pub const SET_MARK: &str = "# --set ";

/// Applies one `KEY=VALUE` (KEY a dotted path such as `schedule.speed_rpm` or
/// `rig.set.teeth`, or a bare rig parameter name as `simulate` takes it: `teeth`,
/// `backlash_mm`, `preset`) to `text`. VALUE is taken as TOML (a number, `true`, `"text"`),
/// or as a string when it is not valid TOML. The key's value must sit on one line of the
/// file. The written line ends with `SET_MARK` and the item.
pub fn apply_override(text: &str, item: &str) -> anyhow::Result<String> {
    let (key, value) = item.split_once('=').with_context(|| {
        format!("--set {item}: expected KEY=VALUE, e.g. schedule.speed_rpm=1500")
    })?;
    let (key, value) = (scenario_key(key.trim()), value.trim());
    let key = key.as_str();
    let value = toml_value(value);
    let mark = format!("{SET_MARK}{}", item.trim());
    let (table, leaf) = match key.rsplit_once('.') {
        Some((table, leaf)) => (table, leaf),
        None => ("", key),
    };
    if leaf.is_empty()
        || !leaf
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        bail!("--set {item}: `{key}` is not a key path like schedule.speed_rpm");
    }
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut current = String::new();
    let mut header_line = (table.is_empty()).then_some(0usize);
    for (i, line) in lines.iter_mut().enumerate() {
        let trimmed = line.trim();
        if trimmed.starts_with("[[") {
            current = format!("[[{}", trimmed.trim_start_matches('['));
            continue;
        }
        if let Some(name) = trimmed.strip_prefix('[') {
            current = name.split(']').next().unwrap_or("").trim().to_string();
            if current == table {
                header_line = Some(i + 1);
            }
            continue;
        }
        if current == table
            && let Some((k, _)) = trimmed.split_once('=')
            && k.trim() == leaf
        {
            *line = format!("{leaf} = {value} {mark}");
            return Ok(lines.join("\n") + "\n");
        }
    }
    match header_line {
        Some(at) => {
            let at = if table.is_empty() {
                first_table_line(&lines)
            } else {
                at
            };
            lines.insert(at, format!("{leaf} = {value} {mark}"));
        }
        None if set_in_inline_table(&mut lines, table, leaf, &value, &mark)? => {}
        None => {
            lines.push(format!("[{table}]"));
            lines.push(format!("{leaf} = {value} {mark}"));
        }
    }
    Ok(lines.join("\n") + "\n")
}

/// The scenario key of a bare name: a rig parameter (`teeth` → `rig.set.teeth`), the
/// backlash (`backlash_mm` → `rig.backlash_mm`) or the preset (`preset` → `rig.preset`);
/// any other key as given.
fn scenario_key(key: &str) -> String {
    match key {
        "backlash_mm" | "preset" => format!("rig.{key}"),
        _ if !key.contains('.') && rig::param_spec(key).is_ok() => format!("rig.set.{key}"),
        _ => key.to_string(),
    }
}

/// Where `table` is written inline in its parent (`[rig]` … `set = { teeth = 30 }` for
/// `rig.set`), sets `leaf` to `value` inside it, on its line; whether it was.
fn set_in_inline_table(
    lines: &mut [String],
    table: &str,
    leaf: &str,
    value: &str,
    mark: &str,
) -> anyhow::Result<bool> {
    let (parent, name) = table.rsplit_once('.').unwrap_or(("", table));
    let mut current = String::new();
    for line in lines.iter_mut() {
        let trimmed = line.trim();
        if let Some(header) = trimmed.strip_prefix('[') {
            current = header
                .trim_matches(|c| c == '[' || c == ']')
                .trim()
                .to_string();
            continue;
        }
        let Some((key, rest)) = trimmed.split_once('=') else {
            continue;
        };
        if current != parent || key.trim() != name || !rest.trim_start().starts_with('{') {
            continue;
        }
        let parsed: toml::Table =
            toml::from_str(&format!("t = {}", rest.trim())).with_context(|| {
                format!("`{table}` is an inline table that spans lines: --set cannot edit it")
            })?;
        let mut inline = match parsed.get("t") {
            Some(toml::Value::Table(t)) => t.clone(),
            _ => return Ok(false),
        };
        let new: toml::Table = toml::from_str(&format!("v = {value}"))
            .with_context(|| format!("`{value}` is not a TOML value"))?;
        if let Some(v) = new.get("v") {
            inline.insert(leaf.to_string(), v.clone());
        }
        let entries: Vec<String> = inline.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        *line = format!("{name} = {{ {} }} {mark}", entries.join(", "));
        return Ok(true);
    }
    Ok(false)
}

fn first_table_line(lines: &[String]) -> usize {
    lines
        .iter()
        .position(|l| l.trim_start().starts_with('['))
        .unwrap_or(lines.len())
}

fn toml_value(value: &str) -> String {
    let probe = format!("v = {value}");
    if toml::from_str::<toml::Table>(&probe).is_ok() {
        value.to_string()
    } else {
        format!("{:?}", value)
    }
}
