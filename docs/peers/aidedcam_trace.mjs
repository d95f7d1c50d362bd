// Writes the moves of aidedcam's g76.js (see aidedcam_g76_driver.mjs) as a plain G00/G32 trace.
const DEC = Number(process.env.DEC || 3);
import { writeFileSync } from 'node:fs';
const mod = await import(process.argv[2] || '/tmp/aidedcam/g76.mjs');
for (const [name, taper, prog] of [['straight', 0, 'O0001'], ['taper', -0.5, 'O0002']]) {
  const depths = mod.g76Depths({ height: 0.92, firstDepth: 0.3, minDepth: 0.05, finishAllow: 0, finishPasses: 1 });
  const moves = mod.g76Moves({ start: { x: 11, z: 2 }, end: { x: 9.08, z: -20 }, depths, height: 0.92, taper });
  const out = ['(aidedcam g76.js trace)', prog, 'G99 G21', 'M03 S500', 'G00 X22.0 Z2.0'];
  for (const m of moves) out.push(`${m.kind === 'thread' ? 'G32' : 'G00'} X${(2 * m.to.x).toFixed(DEC)} Z${m.to.z.toFixed(DEC)}${m.kind === 'thread' ? ' F1.5' : ''}`);
  out.push('G00 X100.0', 'M30');
  writeFileSync(`trace-aidedcam-${name}${DEC === 3 ? '' : '-' + DEC + 'd'}.nc`, out.join('\n') + '\n');
}
