; fatmap's inner loops (Byggmastar, fatmap.txt 1996 and fatmap2.txt 1997); twins of fatmap_loop,
; fatmap16_loop and fatmap_lut_loop in kernel/mappers/fatmap.cpp.

bits 32

%include "fatmap.inc"
%include "loop.inc"

section .text

; fatmap_loop_asm: fatmap.txt's 5-tick loop. The texture sits on a 64 KiB boundary in ebx, so bh:bl
; is the texel's v:u.
;   ecx: u as 24:8 (bl = ch, the whole part)   esi: du as 24:8
;   dh: v fraction   bh: v whole   dl: dv fraction   ah: dv whole   edi: destination   ebp: count
global fatmap_loop_asm
fatmap_loop_asm:
    LOOP_ENTER 0
    mov eax, LOOP_ARG(0)
    mov ebp, [eax + FATMAP_count]
    test ebp, ebp
    jle .done
    mov edi, [eax + FATMAP_dst]
    mov ebx, [eax + FATMAP_texture]
    mov ecx, [eax + FATMAP_u_16_16]
    shr ecx, 8                          ; u as 24:8
    mov esi, [eax + FATMAP_du_16_16]
    shr esi, 8                          ; (logical, as his shr: only the low 16 bits matter)
    mov edx, [eax + FATMAP_v_16_16]           ; dh = byte 1 of v: its fraction's top 8 bits
    mov bh, [eax + FATMAP_v_16_16 + 2]        ; v's whole part, mod 256
    mov dl, [eax + FATMAP_dv_16_16 + 1]       ; dv's fraction byte
    mov ah, [eax + FATMAP_dv_16_16 + 2]       ; dv's whole byte
    mov bl, ch
.pixel:
    add ecx, esi                        ; update u
    mov al, [ebx]                       ; get the texel of the old u, v
    mov bl, ch
    add dh, dl                          ; v fraction
    adc bh, ah                          ; v whole, plus the carry
    mov [edi], al
    inc edi
    dec ebp
    jnz .pixel
.done:
    LOOP_LEAVE 0

; fatmap16_loop_asm: fatmap2.txt's 8:16 loop (Russel Simmons' loop, left to right): the fractions in
; the high halves of eax (u) and edx (v), the wholes in bl (u) and bh (v), the whole steps in dl and
; dh, the fraction steps in the high halves of esi and ebp; ecx counts up to zero.
global fatmap16_loop_asm
fatmap16_loop_asm:
    LOOP_ENTER 0
    mov eax, LOOP_ARG(0)
    mov ecx, [eax + FATMAP_count]
    test ecx, ecx
    jle .done
    mov edi, [eax + FATMAP_dst]
    add edi, ecx                        ; the end: stores go to [edi + ecx], ecx negative
    neg ecx
    mov ebx, [eax + FATMAP_texture]
    mov bl, [eax + FATMAP_u_16_16 + 2]        ; u whole
    mov bh, [eax + FATMAP_v_16_16 + 2]        ; v whole
    mov edx, [eax + FATMAP_v_16_16]
    shl edx, 16                         ; v fraction in the high half
    mov dl, [eax + FATMAP_du_16_16 + 2]       ; du whole
    mov dh, [eax + FATMAP_dv_16_16 + 2]       ; dv whole
    mov esi, [eax + FATMAP_du_16_16]
    shl esi, 16                         ; du fraction
    mov ebp, [eax + FATMAP_dv_16_16]
    shl ebp, 16                         ; dv fraction
    mov eax, [eax + FATMAP_u_16_16]
    shl eax, 16                         ; u fraction (al takes the texel)
.pixel:
    mov al, [ebx]
    add edx, ebp                        ; v fraction (the low half is unchanged: ebp's is 0)
    adc bh, dh
    add eax, esi                        ; u fraction
    adc bl, dl
    mov [edi + ecx], al
    inc ecx
    jnz .pixel
.done:
    LOOP_LEAVE 0

; fatmap_lut_loop_asm: fatmap.txt's table-lookup loop. esi: the scanline's first texel;
; edx: the table; ebx: this pixel's offset; edi: destination; ebp: count.
global fatmap_lut_loop_asm
fatmap_lut_loop_asm:
    LOOP_ENTER 0
    mov eax, LOOP_ARG(0)
    mov ebp, [eax + LUT_count]
    test ebp, ebp
    jle .done
    mov edi, [eax + LUT_dst]
    mov esi, [eax + LUT_source]
    mov edx, [eax + LUT_table]
    mov ebx, [edx]                      ; offset of the first pixel
.pixel:
    mov al, [esi + ebx]
    mov ebx, [edx + 4]                  ; the next pixel's offset (read one past the end: the table has it)
    mov [edi], al
    add edx, 4
    inc edi
    dec ebp
    jnz .pixel
.done:
    LOOP_LEAVE 0
