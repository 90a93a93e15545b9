// The calculator's worker when the page is served over http(s): the module and the worker logic
// are loaded here, off the page's thread.
importScripts('hobsharp-web.js', 'worker-main.js', 'paper-case.js');
hobsharpWorkerMain(self, HobSharpModule, HOBSHARP_PAPER_CASE);
