#!/usr/bin/env node
// Converts the npm package `bunny` (the Stanford bunny as { positions, cells }) to a
// Wavefront OBJ. Used once to make scenes/bunny.obj (see scenes/README.md):
//   cd /tmp && npm pack bunny && tar xzf bunny-1.0.1.tgz
//   node tools/bunny_to_obj.js /tmp/package/index.js > scenes/bunny.obj
// Positions are written with 6 decimals, as in the package; faces keep the package's order
// and winding (OBJ indices are 1-based).
'use strict';
const path = require('path');

const source = process.argv[2];
if (!source) {
  process.stderr.write('usage: node tools/bunny_to_obj.js <path to bunny/index.js>\n');
  process.exit(1);
}
const bunny = require(path.resolve(source));
const lines = [
  '# The Stanford bunny (Stanford 3D Scanning Repository), low-resolution version from the',
  '# npm package "bunny" 1.0.1 by Mikola Lysenko. Converted by tools/bunny_to_obj.js.',
  `# ${bunny.positions.length} vertices, ${bunny.cells.length} triangles.`,
];
for (const p of bunny.positions) lines.push(`v ${p.map((x) => x.toFixed(6)).join(' ')}`);
for (const c of bunny.cells) lines.push(`f ${c.map((i) => i + 1).join(' ')}`);
process.stdout.write(lines.join('\n') + '\n');
