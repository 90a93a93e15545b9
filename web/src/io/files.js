// Files: a download made in the page, and a chosen file's text with a size limit.

export function download(name, text, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// The text of the file chosen in an <input type=file>, which is emptied for the next choice:
// null when none was chosen; throws when the file is empty or larger than maxBytes.
export async function chosenFileText(input, maxBytes, tooLarge) {
  const file = input.files[0];
  input.value = '';
  if (!file) return null;
  if (file.size === 0) throw new Error(`${file.name} is empty.`);
  if (file.size > maxBytes) throw new Error(tooLarge(file.name, file.size));
  return { name: file.name, text: await file.text() };
}
