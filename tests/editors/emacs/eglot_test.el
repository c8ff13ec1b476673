;;; eglot_test.el --- end-to-end test of rung lsp with eglot  -*- lexical-binding: t -*-

;; Run by tests/editors/emacs_eglot_test.cpp as `emacs --batch -l rung-eglot.el -l eglot_test.el'
;; in a copy of tests/editors/fixture. Opens PLC_PRG.st, starts eglot as `M-x eglot' does, waits
;; for flymake to show rung's diagnostics, jumps to a definition in another file with xref and
;; asks for hover when the server offers it. Writes what Emacs saw as JSON to
;; $RUNG_EDITOR_RESULT; the C++ test asserts on it.

(require 'json)
(require 'flymake)
(require 'xref)

(defvar rung-test-result nil "Alist of what the test saw, written as JSON at the end.")

(defun rung-test-finish (&optional error-message)
  (when error-message
    (push (cons 'error error-message) rung-test-result))
  (with-temp-file (getenv "RUNG_EDITOR_RESULT")
    (insert (json-encode rung-test-result)))
  (kill-emacs 0))

(defun rung-test-wait-for (what predicate &optional seconds)
  "Lets eglot's process run until PREDICATE holds; signals an error naming WHAT after SECONDS."
  (let ((deadline (+ (float-time) (or seconds 10))))
    (while (not (funcall predicate))
      (when (> (float-time) deadline)
        (error "timed out waiting for %s" what))
      (accept-process-output nil 0.05))))

(defun rung-test-diagnostics ()
  (mapcar (lambda (d)
            (save-excursion
              (goto-char (flymake-diagnostic-beg d))
              `((line . ,(line-number-at-pos))
                (col . ,(current-column))
                (type . ,(symbol-name (flymake-diagnostic-type d)))
                (text . ,(flymake-diagnostic-text d)))))
          (flymake-diagnostics)))

(defun rung-test-goto (line word)
  (goto-char (point-min))
  (forward-line (1- line))
  (search-forward word (line-end-position))
  (goto-char (match-beginning 0)))

(defun rung-test-run ()
  (find-file (expand-file-name "src/PLC_PRG.st" (getenv "RUNG_EDITOR_PROJECT")))
  (push (cons 'mode (symbol-name major-mode)) rung-test-result)
  (call-interactively #'eglot)
  (rung-test-wait-for "eglot to connect" #'eglot-current-server)
  (rung-test-wait-for "flymake to show the diagnostics" #'flymake-diagnostics)
  (push (cons 'diagnostics (rung-test-diagnostics)) rung-test-result)
  (push (cons 'hover_offered (if (eglot--server-capable :hoverProvider) t :json-false)) rung-test-result)
  (when (eglot--server-capable :hoverProvider)
    (rung-test-goto 3 "FB_Mixer")
    (push (cons 'hover
                (jsonrpc-request (eglot-current-server) :textDocument/hover
                                 (eglot--TextDocumentPositionParams)))
          rung-test-result))
  (rung-test-goto 9 "bMotor")
  (let ((from (current-buffer)))
    (call-interactively #'xref-find-definitions)
    (rung-test-wait-for "xref to jump" (lambda () (not (eq (current-buffer) from)))))
  (push `(definition . ((file . ,(file-name-nondirectory buffer-file-name))
                        (line . ,(line-number-at-pos))
                        (col . ,(current-column))))
        rung-test-result))

(run-at-time (/ (string-to-number (or (getenv "RUNG_EDITOR_TIME_LIMIT_MS") "20000")) 1000.0) nil
             (lambda () (rung-test-finish "the eglot test did not finish in time")))
(condition-case err
    (progn (rung-test-run) (rung-test-finish))
  (error (rung-test-finish (error-message-string err))))

;;; eglot_test.el ends here
