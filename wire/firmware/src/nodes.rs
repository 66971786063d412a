//! The nodes behind a gateway (MD810's bridge mode: CANopen slaves): the
//! words the gateway forwards to each node and from it, and the event a
//! node reports, which the gateway's diagnosis carries. No manual gives the
//! nodes' data: the words a node sends are this model's own.

use crate::card::{NodeEvent, NodeSetup};

/// The most bytes of output a gateway forwards: DP's 244 (IEC 61158-6-3).
pub const MAX_DATA: usize = 244;

/// The nodes as the gateway sees them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Nodes {
    /// The output the master last sent, as the gateway forwarded it.
    received: [u8; MAX_DATA],
    received_len: usize,
    /// What a node reported last.
    event: Option<NodeEvent>,
}

impl Default for Nodes {
    fn default() -> Self {
        Nodes {
            received: [0; MAX_DATA],
            received_len: 0,
            event: None,
        }
    }
}

impl Nodes {
    /// Word `word` (from 0) of what `node` sends: this model's own values,
    /// the node number in the high byte and the word's number from 1 in
    /// the low byte, so each word says where it comes from.
    pub const fn sent_word(node: u8, word: usize) -> u16 {
        (node as u16) << 8 | (word as u16 + 1)
    }

    /// The gateway forwards the master's `outputs` to the nodes of `setup`
    /// and fills `inputs` with what the nodes send.
    pub fn exchange(&mut self, setup: &NodeSetup, outputs: &[u8], inputs: &mut [u8]) {
        let len = outputs.len().min(MAX_DATA);
        self.received[..len].copy_from_slice(&outputs[..len]);
        self.received_len = len;
        for node in setup.nodes() {
            for word in 0..usize::from(node.input_words) {
                let at = node.input_offset + 2 * word;
                let value = Self::sent_word(node.node, word);
                inputs[at..at + 2].copy_from_slice(&value.to_be_bytes());
            }
        }
    }

    /// The words `node` of `setup` last received, as bytes.
    pub fn received(&self, setup: &NodeSetup, node: u8) -> Option<&[u8]> {
        let data = setup.nodes().find(|n| n.node == node)?;
        let end = data.output_offset + 2 * usize::from(data.output_words);
        self.received[..self.received_len].get(data.output_offset..end)
    }

    /// A node reports `event`, or the event is over (`None`).
    pub fn report(&mut self, event: Option<NodeEvent>) {
        self.event = event;
    }

    pub fn event(&self) -> Option<NodeEvent> {
        self.event
    }
}
