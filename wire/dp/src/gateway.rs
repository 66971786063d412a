//! A gateway's exchange (MD810's bridge mode): the master puts nodes in use
//! and sets each one's words by the parameters' GSD names (2.4 step 4), and
//! plugs word modules, chosen from the GSD by what their config bytes
//! declare, whose words make the nodes' totals (step 5). The slave forwards
//! the output to the nodes and the nodes' words back; the master finds each
//! node's words where the nodes in use follow each other in ascending
//! number.

use gsd_parser::{Module, PrmValueConstraint};
use profirust::Baudrate;
use wire_firmware::nodes::Nodes;

use crate::exchange::{Startup, Target};
use crate::gsd::data_lengths;
use crate::manuals::{NodeExchange, NodeParameters};
use crate::report::{failed, words};
use crate::slave::Plugged;

/// The words one node carries each way.
#[derive(Clone, Copy, Debug)]
struct NodeWords {
    node: u8,
    input: usize,
    output: usize,
}

impl Target {
    /// A start-up for every module size the GSD offers (an input and an
    /// output module of as many words), then the manual's exchanges.
    pub fn gateway(
        &self,
        names: &NodeParameters,
        exchanges: &[NodeExchange],
        baudrate: Baudrate,
    ) -> Vec<bool> {
        let mut sizes: Vec<usize> = self
            .gsd
            .modules()
            .filter_map(|m| data_lengths(&m.config).ok())
            .map(|(input, output)| input.max(output) / 2)
            .collect();
        sizes.sort_unstable();
        sizes.dedup();
        let every_size = sizes.into_iter().map(|words| NodeExchange {
            title: "",
            input_words: words,
            output_words: words,
            steps: &[],
        });
        every_size
            .map(|exchange| self.node_exchange(names, &exchange, baudrate))
            .chain(
                exchanges
                    .iter()
                    .map(|e| self.node_exchange(names, e, baudrate)),
            )
            .collect()
    }

    /// The start-up with one word each way: the base of the refusals.
    pub fn gateway_base(&self, names: &NodeParameters) -> Result<Startup, String> {
        self.node_startup(names, String::new(), 1, 1)
    }

    fn node_exchange(
        &self,
        names: &NodeParameters,
        exchange: &NodeExchange,
        baudrate: Baudrate,
    ) -> bool {
        let title = match exchange.title {
            "" => format!(
                "modules of {} each way",
                match exchange.input_words {
                    1 => "1 word".to_string(),
                    n => format!("{n} words"),
                }
            ),
            title => title.to_string(),
        };
        let startup =
            match self.node_startup(names, title, exchange.input_words, exchange.output_words) {
                Ok(startup) => startup,
                Err(why) => return failed(&why),
            };
        let Some(mut bus) = self.configure(&startup, baudrate) else {
            return false;
        };
        let nodes = match self.nodes(names, exchange.input_words, exchange.output_words) {
            Ok(nodes) => nodes,
            Err(why) => return failed(&why),
        };
        let mut passed = self.check_prm(&bus, &startup, &values(names, &nodes));
        // The master's words, numbered from 0x8001: this test's own values.
        let outputs: Vec<u8> = (0..exchange.output_words)
            .flat_map(|i| (0x8001 + i as u16).to_be_bytes())
            .collect();
        match bus.exchange(&outputs) {
            Ok(inputs) => {
                println!("    Data_Exch  out {}", words(&outputs));
                println!("               in  {}", words(&inputs));
                passed &= check_nodes(&bus, &nodes, &outputs, &inputs);
            }
            Err(outcome) => passed &= failed(&format!("Data_Exchange: {outcome:?}")),
        }
        for step in exchange.steps {
            passed &= self.step(&mut bus, &startup, step);
        }
        passed
    }

    /// The start-up that carries `input` and `output` words: the nodes'
    /// parameters set by name, and modules whose words make the totals.
    fn node_startup(
        &self,
        names: &NodeParameters,
        title: String,
        input: usize,
        output: usize,
    ) -> Result<Startup, String> {
        let nodes = self.nodes(names, input, output)?;
        let mut modules = self.modules_for(input * 2, true)?;
        modules.extend(self.modules_for(output * 2, false)?);
        self.startup(title, &modules, &values(names, &nodes))
    }

    /// As few nodes as carry `input` and `output` words, each at most the
    /// words its parameter allows (the GSD's range), in ascending number.
    fn nodes(
        &self,
        names: &NodeParameters,
        input: usize,
        output: usize,
    ) -> Result<Vec<NodeWords>, String> {
        let first = names
            .input_words
            .replace("{n}", &names.first_node.to_string());
        let most = self
            .gsd
            .parameters()
            .find(|p| p.name == first)
            .and_then(|p| match p.constraint {
                PrmValueConstraint::MinMax(_, max) => usize::try_from(*max).ok(),
                _ => None,
            })
            .filter(|most| *most > 0)
            .ok_or_else(|| format!("the GSD has no range for {first:?}"))?;
        let count = input.div_ceil(most).max(output.div_ceil(most)).max(1);
        Ok((0..count)
            .map(|i| NodeWords {
                node: names.first_node + i as u8,
                input: input.saturating_sub(i * most).min(most),
                output: output.saturating_sub(i * most).min(most),
            })
            .collect())
    }

    /// The GSD's modules of one direction whose data make `len` bytes: the
    /// longest first, as an engineer fills a total.
    fn modules_for(&self, len: usize, input: bool) -> Result<Vec<&Module>, String> {
        let mut sized: Vec<(usize, &Module)> = self
            .gsd
            .modules()
            .filter_map(|m| {
                let (i, o) = data_lengths(&m.config).ok()?;
                match (input, i, o) {
                    (true, i, 0) if i > 0 => Some((i, m)),
                    (false, 0, o) if o > 0 => Some((o, m)),
                    _ => None,
                }
            })
            .collect();
        sized.sort_by_key(|(size, _)| std::cmp::Reverse(*size));
        let mut left = len;
        let mut modules = Vec::new();
        for (size, module) in sized {
            while left >= size {
                modules.push(module);
                left -= size;
            }
        }
        if left == 0 {
            Ok(modules)
        } else {
            Err(format!("no modules of the GSD make {len} bytes"))
        }
    }
}

/// The node parameters by name: the count, then each node's words.
fn values(names: &NodeParameters, nodes: &[NodeWords]) -> Vec<(String, i64)> {
    let mut values = vec![(names.count.to_string(), nodes.len() as i64)];
    for node in nodes {
        let n = node.node.to_string();
        values.push((names.input_words.replace("{n}", &n), node.input as i64));
        values.push((names.output_words.replace("{n}", &n), node.output as i64));
    }
    values
}

/// Each node received its words of the output, and the input holds each
/// node's words, the nodes in ascending number.
fn check_nodes(bus: &crate::bus::Bus, nodes: &[NodeWords], outputs: &[u8], inputs: &[u8]) -> bool {
    let slave = &bus.station.slave;
    let Some(Plugged::Nodes(setup)) = slave.plugged() else {
        return failed("the slave plugged no nodes");
    };
    let (mut input_at, mut output_at) = (0, 0);
    for node in nodes {
        let sent = &outputs[output_at..output_at + 2 * node.output];
        if slave.nodes.received(setup, node.node) != Some(sent) {
            return failed(&format!(
                "node {}, output byte {output_at}: the master sent {}, the node received {:?}",
                node.node,
                words(sent),
                slave.nodes.received(setup, node.node).map(words)
            ));
        }
        for word in 0..node.input {
            let at = input_at + 2 * word;
            let want = Nodes::sent_word(node.node, word);
            let got = inputs
                .get(at..at + 2)
                .map(|b| u16::from_be_bytes([b[0], b[1]]));
            if got != Some(want) {
                return failed(&format!(
                    "node {}, input byte {at}: the node sent 0x{want:04X}, the master read {got:04X?}",
                    node.node
                ));
            }
        }
        input_at += 2 * node.input;
        output_at += 2 * node.output;
    }
    println!(
        "    ok: each of the {} nodes received its words and sent its own",
        nodes.len()
    );
    true
}
