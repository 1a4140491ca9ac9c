// Makes the simulated robot's camera frames (src/robots/simulator/camera-frames.json):
// small JPEGs of a room with a participant-sized shape that moves, drawn as SVG
// and encoded by sharp (already installed with Next.js). Run once:
// `node scripts/simulator-camera-frames.mjs`; the simulator only reads the file.
import { writeFileSync } from "node:fs";
import sharp from "sharp";

const FRAMES = 12;
const [W, H] = [160, 120];
const frames = [];
for (let i = 0; i < FRAMES; i++) {
  const x = 30 + Math.round(100 * (0.5 - 0.5 * Math.cos((2 * Math.PI * i) / FRAMES)));
  const svg = `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}">
    <rect width="${W}" height="${H}" fill="#dfe7ef"/>
    <rect y="80" width="${W}" height="40" fill="#b9a58c"/>
    <circle cx="${x}" cy="38" r="12" fill="#f2c9a0"/>
    <rect x="${x - 14}" y="52" width="28" height="40" rx="6" fill="#3b6ea5"/>
    <text x="6" y="114" font-family="monospace" font-size="10" fill="#333">SIM CAM ${i + 1}/${FRAMES}</text>
  </svg>`;
  frames.push((await sharp(Buffer.from(svg)).jpeg({ quality: 70 }).toBuffer()).toString("base64"));
}
writeFileSync(
  new URL("../src/robots/simulator/camera-frames.json", import.meta.url),
  `${JSON.stringify({ format: "jpeg", width: W, height: H, frames }, null, 1)}\n`,
);
console.log(`${FRAMES} frames, ${frames.reduce((n, f) => n + f.length, 0)} base64 characters`);
