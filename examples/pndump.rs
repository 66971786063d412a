fn main() {
    let path = std::env::args().nth(1).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    let name = std::path::Path::new(&path)
        .file_name()
        .unwrap()
        .to_str()
        .unwrap();
    if let Some(gsdc::device::Device::Pn(d)) = gsdc::device::read(&bytes, Some(name)) {
        println!("identity:");
        for a in &d.identity {
            println!("  {} = {}", a.name, a.value);
        }
        println!(
            "languages {:?} schema {:?} vendor {:?} dev {:?}",
            d.languages, d.schema_version, d.vendor_id, d.device_id
        );
        for dap in &d.daps {
            println!(
                "DAP {} {:?} name {:?}",
                dap.item.id,
                dap.item.ident,
                dap.item.name.as_ref().map(|t| t.primary.to_string())
            );
            for a in &dap.item.attributes {
                println!("  {} = {}", a.name, a.value);
            }
            for s in &dap.item.submodules {
                println!("  sub {:?} {} {:?} {:?}", s.kind, s.id, s.ident, s.subslot);
                for a in &s.attributes {
                    println!("    {} = {}", a.name, a.value);
                }
            }
            for r in &dap.useable_modules {
                println!(
                    "  use {} {:?}",
                    r.target,
                    r.attributes
                        .iter()
                        .map(|a| format!("{}={}", a.name, a.value))
                        .collect::<Vec<_>>()
                );
            }
        }
        for m in d.modules.iter().take(2) {
            println!("MOD {} {:?}", m.id, m.ident);
            for a in &m.attributes {
                println!("  {} = {}", a.name, a.value);
            }
            for s in &m.submodules {
                println!("  sub {:?} {} {:?}", s.kind, s.id, s.ident);
                for a in &s.attributes {
                    println!("    {} = {}", a.name, a.value);
                }
                for r in &s.records {
                    println!(
                        "    rec {} {:?} len {:?} fields {}",
                        r.index,
                        r.name.as_ref().map(|t| t.primary.to_string()),
                        r.data.length,
                        r.data.fields.len()
                    );
                    for a in &r.attributes {
                        println!("      {} = {}", a.name, a.value);
                    }
                }
                if let Some(i) = &s.io.input {
                    for it in &i.items {
                        println!(
                            "    in {} {:?} bits {}",
                            it.data_type,
                            it.text.as_ref().map(|t| t.primary.to_string()),
                            it.bits.len()
                        );
                    }
                }
            }
        }
        println!(
            "other {:?}",
            d.other
                .iter()
                .map(|a| a.name.to_string())
                .collect::<Vec<_>>()
        );
    }
}
