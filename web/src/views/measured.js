// The measured data and the correction's verdict, each job in its own view, their state in the
// store (web/src/measurement.js keeps it): the box (measured-box.js), its preview
// (measured-preview.js), the file buttons (measured-files.js), the message beside the box
// (measured-message.js), the verdict (verdict.js). Mounted in this order, which is the order
// their listeners run in.
import { giveText, mountMeasurement } from '../measurement.js';
import { mountMeasuredBox } from './measured-box.js';
import { mountMeasuredPreview } from './measured-preview.js';
import { mountMeasuredFiles } from './measured-files.js';
import { mountMeasuredMessage } from './measured-message.js';
import { mountVerdict } from './verdict.js';

export function mountMeasured(store) {
  mountMeasuredBox(store);
  mountMeasuredPreview(store);
  mountMeasuredFiles(store);
  mountMeasurement(store);
  mountMeasuredMessage(store);
  mountVerdict(store);
  return {
    // The text of a measured grid that came with a loaded case (set aside or used), the machine
    // error's, or none (the next run).
    setText: (text) => giveText(store, text),
  };
}
