;;; rung-eglot.el --- rung's language server in Emacs with eglot  -*- lexical-binding: t -*-

;; The setup docs/editors/emacs.md shows; the end-to-end test loads this file as the user's
;; configuration, so the documented setup is the tested one. RUNG_LSP_COMMAND lets the test
;; point at the freshly built binary; users have `rung' on PATH.

(require 'eglot)

;; A major mode for IEC 61131-3 files, so that eglot knows which buffers belong to rung.
(define-derived-mode iec61131-mode prog-mode "IEC-61131"
  "Major mode for IEC 61131-3 Structured Text, IL and SFC."
  (setq-local comment-start "// ")
  (setq-local comment-end ""))
(add-to-list 'auto-mode-alist
             '("\\.\\(st\\|il\\|sfc\\|exp\\|EXP\\|TcPOU\\|TcDUT\\|TcGVL\\|TcIO\\)\\'" . iec61131-mode))

(add-to-list 'eglot-server-programs
             `(iec61131-mode . (,(or (getenv "RUNG_LSP_COMMAND") "rung") "lsp")))

;; The project is the folder with rung.toml, also when it is not in a Git repository.
(defun rung-project-find (dir)
  (let ((root (locate-dominating-file dir "rung.toml")))
    (and root (cons 'transient (expand-file-name root)))))
(add-hook 'project-find-functions #'rung-project-find)

(add-hook 'iec61131-mode-hook #'eglot-ensure)

;;; rung-eglot.el ends here
